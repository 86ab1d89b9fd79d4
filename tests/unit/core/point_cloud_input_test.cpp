// The input checks (point_cloud_input), reached as a user reaches them, through the
// contraction: a clear InvalidInput for a cloud that cannot be processed, never a crash.
#include <pcskeleton/contraction/laplacian_contraction.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <limits>

using namespace pcskeleton;

namespace {

std::string errorOf(const PointList& points, const ContractionParameters& p = {}) {
    try {
        LaplacianContraction::run(points, p);
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(BadInput, EmptyCloud) { EXPECT_NE(errorOf({}).find("empty"), std::string::npos); }

TEST(BadInput, FewerPointsThanNeighbours) {
    const std::string error = errorOf(shapes::sphere(8, 1.0));
    EXPECT_NE(error.find("Too few points"), std::string::npos) << error;
    ContractionParameters p;
    p.neighbourCount = 20;
    EXPECT_NE(errorOf(shapes::sphere(15, 1.0), p).find("at least 21"), std::string::npos);
}

TEST(BadInput, NaNAndInfiniteCoordinates) {
    PointList points = shapes::sphere(500, 1.0);
    points[17].y() = std::numeric_limits<double>::quiet_NaN();
    points[40].x() = std::numeric_limits<double>::infinity();
    const std::string error = errorOf(points);
    EXPECT_NE(error.find("2 of 500 points have NaN or infinite"), std::string::npos) << error;
    EXPECT_NE(error.find("point 17"), std::string::npos) << error;
}

TEST(BadInput, CollinearPoints) {
    PointList line;
    for (int i = 0; i < 100; ++i) line.emplace_back(i, 2 * i, -i);
    EXPECT_NE(errorOf(line).find("straight line"), std::string::npos);
}

TEST(BadInput, AllPointsIdentical) {
    const PointList same(50, Point(1, 2, 3));
    EXPECT_NE(errorOf(same).find("1 distinct points (50 with duplicates)"), std::string::npos) << errorOf(same);
}
