// Bad and unusual input: a clear InvalidInput or a sensible result, never a crash or hang.
#include <pcskeleton/laplacian_contraction.h>
#include <pcskeleton/sampled_shapes.h>

#include <gtest/gtest.h>

#include <cmath>
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

bool allFinite(const PointList& points) {
    return std::all_of(points.begin(), points.end(), [](const Point& p) { return p.allFinite(); });
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

TEST(BadInput, InvalidParameters) {
    ContractionParameters p;
    p.contractionScale = 0.5;
    EXPECT_NE(errorOf(shapes::sphere(100, 1.0), p).find("s_L"), std::string::npos);
    p = {};
    p.maxIterations = 0;
    EXPECT_FALSE(errorOf(shapes::sphere(100, 1.0), p).empty());
}

TEST(UnusualInput, ExactDuplicatesFollowTheirTwin) {
    PointList cloud = shapes::cylinder(2000, 0.1, 1.0, true);
    const std::size_t unique = cloud.size();
    for (std::size_t i = 0; i < unique; i += 3) cloud.push_back(cloud[i]);
    const ContractionResult result = LaplacianContraction::run(cloud);
    ASSERT_EQ(result.contracted.size(), cloud.size());
    ASSERT_TRUE(allFinite(result.contracted));
    for (std::size_t i = unique, j = 0; i < cloud.size(); ++i, j += 3) EXPECT_EQ(result.contracted[i], result.contracted[j]);
    double distance = 0;
    for (const Point& p : result.contracted) distance += shapes::distanceToSegment(p, Point(0, 0, 0), Point(0, 0, 1));
    EXPECT_LT(distance / cloud.size(), 0.01);
}

TEST(UnusualInput, FlatCloudContractsWithinItsPlane) {
    // A flat sheet is a surface with a boundary: it contracts from the rim, in its plane.
    PointList disc;
    for (const Point& p : shapes::sphere(3000, 1.0)) disc.emplace_back(p.x(), p.y(), 0.0);
    const ContractionResult result = LaplacianContraction::run(disc);
    ASSERT_TRUE(allFinite(result.contracted));
    for (const Point& p : result.contracted) EXPECT_NEAR(p.z(), 0.0, 1e-9);
}

TEST(UnusualInput, FarFromTheOriginAndTinyOrHugeScales) {
    const PointList cloud = shapes::cylinder(2000, 0.1, 1.0, true);
    for (double scale : {1e-6, 1e6}) {
        const Point offset(1e6, -2e6, 3e6);
        PointList moved;
        for (const Point& p : cloud) moved.push_back(p * scale + offset);
        const ContractionResult result = LaplacianContraction::run(moved);
        ASSERT_TRUE(allFinite(result.contracted));
        double distance = 0;
        for (const Point& p : result.contracted)
            distance += shapes::distanceToSegment((p - offset) / scale, Point(0, 0, 0), Point(0, 0, 1));
        EXPECT_LT(distance / cloud.size(), 0.01) << "scale " << scale;
    }
}

TEST(UnusualInput, DisconnectedComponentsContractSeparately) {
    PointList cloud = shapes::torus(3000, 1.0, 0.25, 1);
    const std::size_t first = cloud.size();
    for (const Point& p : shapes::torus(3000, 1.0, 0.25, 2)) cloud.push_back(p + Point(4, 0, 0));
    const ContractionResult result = LaplacianContraction::run(cloud);
    ASSERT_TRUE(allFinite(result.contracted));
    double before = 0, after = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const Point centre = i < first ? Point(0, 0, 0) : Point(4, 0, 0);
        auto toCircle = [&](const Point& p) {
            const Point q = p - centre;
            return std::hypot(std::hypot(q.x(), q.y()) - 1.0, q.z());
        };
        before += toCircle(cloud[i]);
        after += toCircle(result.contracted[i]);
    }
    EXPECT_LT(after, 0.2 * before);
}
