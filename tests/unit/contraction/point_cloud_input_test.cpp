// The input checks (point_cloud_input), reached as a user reaches them, through the
// contraction: a clear InvalidInput for a cloud that cannot be processed, never a crash.
#include <pcskeleton/contraction/laplacian_contraction.h>
#include <pcskeleton/contraction/point_cloud_input.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <random>

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

TEST(BadInput, EmptyCloud) { EXPECT_EQ(errorOf({}), "The cloud is empty: it has no points."); }

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

// Two spheres of radius 1 a hundred million apart: to the precision of the cloud's extent
// they are two points on a line, refused as such, and the message says how far off the line
// they are and what that can mean. A line off no axis, exact but for rounding, gets the
// plain message.
TEST(BadInput, PartsVeryFarApartForTheirSizeAreALineAndSaySo) {
    PointList parts = shapes::sphere(500, 1.0);
    for (const Point& p : shapes::sphere(500, 1.0)) parts.push_back(p + Point(1e8, 0, 0));
    const std::string error = errorOf(parts);
    EXPECT_NE(error.find("straight line, within 1e-08 of its length"), std::string::npos) << error;
    EXPECT_NE(error.find("parts very far apart for their size"), std::string::npos) << error;

    PointList line;
    for (int i = 0; i < 100; ++i) line.push_back(Point(1.1, 2.2, 3.3) + 0.37 * i * Point(1, 2, -1));
    EXPECT_EQ(errorOf(line), "All points lie on one straight line: such a cloud is already a curve and has no "
                             "surface to contract.");
}

TEST(BadInput, AllPointsIdentical) {
    const PointList same(50, Point(1, 2, 3));
    EXPECT_NE(errorOf(same).find("1 distinct points (50 with duplicates)"), std::string::npos) << errorOf(same);
}

// Coordinates whose squared differences overflow or underflow are refused with the reason;
// within the range every scale gives the same skeleton (curve_skeleton_test).
TEST(BadInput, ScalesBeyondWhatSquaredDistancesHold) {
    const PointList torus = shapes::torus(3000, 1.0, 0.25);
    PointList huge, tiny;
    for (const Point& p : torus) huge.push_back(p * 1e154), tiny.push_back(p * 1e-200);
    EXPECT_NE(errorOf(huge).find("coordinates up to 1.25e+154"), std::string::npos) << errorOf(huge);
    EXPECT_NE(errorOf(tiny).find("span only"), std::string::npos) << errorOf(tiny);
}

TEST(ExactDuplicates, GroupsAreNumberedByFirstAppearance) {
    const PointList points{Point(1, 0, 0), Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0), Point(0, 0, 0)};
    const ExactDuplicates d = findExactDuplicates(points);
    ASSERT_TRUE(d.any());
    EXPECT_EQ(d.groupOf, (std::vector<int>{0, 1, 0, 2, 1}));
    EXPECT_EQ(d.firstOf, (std::vector<int>{0, 1, 3}));
    EXPECT_FALSE(findExactDuplicates({Point(0, 0, 0), Point(1, 0, 0)}).any());
}

// The order in which a file lists its points is no property of the shape: the cloud the
// algorithm works on puts the points in an order their positions alone fix, so a
// permutation of the input (with duplicates and an outlier) gives the same cloud, and each
// input point still finds its own position.
TEST(NormalizedCloud, ThePointsOrderDependsOnTheirPositionsOnly) {
    PointList points = shapes::torus(3000, 1.0, 0.25, 3);
    for (std::size_t i = 0; i < 50; ++i) points.push_back(points[37 * i]);
    points.push_back(Point(9, 9, 9));
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(5));
    PointList shuffled;
    for (std::size_t i : order) shuffled.push_back(points[i]);

    const NormalizedCloud a = normalizeCloud(points, 31, {}), b = normalizeCloud(shuffled, 31, {});
    ASSERT_EQ(a.points.size(), 3000u);
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.outliers.size(), 1u);
    ASSERT_EQ(b.inputSize(), points.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        ASSERT_EQ(b.isOutlier(k), a.isOutlier(order[k])) << "input point " << order[k];
        ASSERT_EQ(b.inputPosition(k), a.inputPosition(order[k])) << "input point " << order[k];
        ASSERT_LT((b.inputPosition(k) - shuffled[k]).norm(), 1e-12) << "input point " << order[k];
    }
}

// Parameters that are not finite or beyond any sensible value are refused by name.
TEST(BadInput, NonFiniteAndAbsurdParameters) {
    const PointList torus = shapes::torus(2000, 1.0, 0.25);
    const double inf = std::numeric_limits<double>::infinity();
    ContractionParameters p;
    p.initialContractionWeight = inf;
    EXPECT_NE(errorOf(torus, p).find("W_L0"), std::string::npos) << errorOf(torus, p);
    p = {};
    p.contractionScale = 1e308;
    EXPECT_NE(errorOf(torus, p).find("between 1 and 1000"), std::string::npos) << errorOf(torus, p);
    p = {};
    p.terminationThreshold = inf;
    EXPECT_NE(errorOf(torus, p).find("below 1"), std::string::npos) << errorOf(torus, p);
    p = {};
    p.outliers.isolationFactor = inf;
    EXPECT_NE(errorOf(torus, p).find("finite"), std::string::npos) << errorOf(torus, p);
    p = {};
    p.maxAttractionWeight = std::nan("");
    EXPECT_NE(errorOf(torus, p).find("up to 1e8"), std::string::npos) << errorOf(torus, p);
}
