// Bone radii: a node along a straight tube gets the tube's radius, measured across the bone,
// with the noise and an off-axis node taken out; tips, junctions and one-sided nodes are
// not measured.
#include <pcskeleton/finishing/bone_radii.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pcskeleton {
namespace {

constexpr double kTube = 0.1;
constexpr double kSpacing = 1.0;  // the nodes' own

// Three nodes along x, at x = 0, 1, 2, the middle one `offset` off the tube's axis, owning
// 2000 points of the tube's wall within half a unit along x, moved by Gaussian noise of
// deviation `noise` in every direction. Points of the wall over `sweep` radians only.
SkeletonGraph middleOfATube(double noise, const Point& offset, PointList& points, double sweep = 2 * M_PI) {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(0, 1);
    std::normal_distribution<double> gaussian(0, noise > 0 ? noise : 1);
    SkeletonGraph g;
    g.nodes = {Point(0, 0, 0), Point(1, 0, 0) + offset, Point(2, 0, 0)};
    g.radii = {0.5, 0.5, 0.5};
    g.edges = {{0, 1}, {1, 2}};
    for (int i = 0; i < 2000; ++i) {
        const double angle = sweep * unit(random);
        Point p(0.5 + unit(random), kTube * std::cos(angle), kTube * std::sin(angle));
        if (noise > 0) p += Point(gaussian(random), gaussian(random), gaussian(random));
        points.push_back(p);
        g.pointNode.push_back(1);
    }
    return g;
}

double meanDistance(const SkeletonGraph& g, const PointList& points) {
    return meanDistanceToNodes(points, g.pointNode, g.nodes)[1];
}

TEST(BoneRadii, AreTheTubesAcrossTheBoneWhereTheNodesOwnDistanceIsFarLarger) {
    PointList points;
    const SkeletonGraph g = middleOfATube(0.0, Point::Zero(), points);
    const std::vector<double> radii = boneRadii(g, points, kSpacing);
    EXPECT_NEAR(radii[1], kTube, 0.001);
    EXPECT_GT(meanDistance(g, points), 2 * kTube);  // the points spread a unit along the bone
    EXPECT_EQ(radii[0], 0.0);  // tips own no points here, and are no bone nodes
    EXPECT_EQ(radii[2], 0.0);
}

TEST(BoneRadii, TakeOutNoiseOfAThirdOfTheRadius) {
    PointList points;
    const SkeletonGraph g = middleOfATube(kTube / 3, Point::Zero(), points);
    EXPECT_NEAR(boneRadii(g, points, kSpacing)[1], kTube, 0.02 * kTube);
    // Measured across the bone but without the correction, the radius would be some 5% more.
    double across = 0;
    for (const Point& p : points) across += std::hypot(p.y(), p.z());
    EXPECT_GT(across / double(points.size()), 1.04 * kTube);
}

TEST(BoneRadii, TakeOutANodeOffTheAxis) {
    PointList points;
    const SkeletonGraph g = middleOfATube(0.0, Point(0, 0.4 * kTube, 0), points);
    EXPECT_NEAR(boneRadii(g, points, kSpacing)[1], kTube, 0.03 * kTube);
}

TEST(BoneRadii, LeaveOneSidedNodesAndJunctionsAsTheyAre) {
    PointList half;
    SkeletonGraph g = middleOfATube(0.0, Point::Zero(), half, M_PI);
    EXPECT_EQ(boneRadii(g, half, kSpacing)[1], 0.0);
    measureBoneRadii(g, half, kSpacing);
    EXPECT_EQ(g.radii[1], 0.5);

    PointList points;
    SkeletonGraph junction = middleOfATube(0.0, Point::Zero(), points);
    junction.nodes.push_back(Point(1, 1, 0));
    junction.radii.push_back(0.5);
    junction.edges.push_back({1, 3});
    EXPECT_EQ(boneRadii(junction, points, kSpacing)[1], 0.0);
}

TEST(BoneRadii, NeverLeaveANodeAwayFromItsData) {
    // The node's points all lie 0.3 to 0.5 along the bone from it: with the tube's radius it
    // would be farther from its nearest point than its radius and half a node spacing of 0.2.
    PointList points;
    SkeletonGraph g = middleOfATube(0.0, Point::Zero(), points);
    for (Point& p : points) p.x() = 1.3 + 0.2 * (p.x() - 0.5);
    EXPECT_EQ(boneRadii(g, points, 0.2)[1], 0.0);
    EXPECT_NEAR(boneRadii(g, points, 0.5)[1], kTube, 0.001);  // within the slack of a larger spacing
}

}  // namespace
}  // namespace pcskeleton
