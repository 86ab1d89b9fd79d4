// Distance to a skeleton's bones and the radius interpolated there, against values worked
// out by hand.
#include <pcskeleton/core/errors.h>
#include <pcskeleton/skeleton/skeleton_distance.h>

#include <gtest/gtest.h>

namespace pcskeleton {
namespace {

// One bone along x from 0 to 1, radius 0.1 at the start and 0.3 at the end.
SkeletonGraph taperedBone() {
    SkeletonGraph g;
    g.nodes = {Point(0, 0, 0), Point(1, 0, 0)};
    g.radii = {0.1, 0.3};
    g.edges = {{0, 1}};
    return g;
}

TEST(SkeletonDistance, RadiusIsInterpolatedAlongTheNearestBone) {
    const SkeletonDistance distance(taperedBone());
    const SkeletonProximity middle = distance.nearest(Point(0.5, 0.2, 0));
    EXPECT_NEAR(middle.distance, 0.2, 1e-9);
    EXPECT_NEAR(middle.radius, 0.2, 1e-9);
    const SkeletonProximity quarter = distance.nearest(Point(0.25, 0, -0.5));
    EXPECT_NEAR(quarter.distance, 0.5, 1e-9);
    EXPECT_NEAR(quarter.radius, 0.15, 1e-9);
}

TEST(SkeletonDistance, BeyondAnEndTheEndNodeIsNearest) {
    const SkeletonDistance distance(taperedBone());
    const SkeletonProximity past = distance.nearest(Point(2, 0, 0));
    EXPECT_NEAR(past.distance, 1.0, 1e-9);
    EXPECT_NEAR(past.radius, 0.3, 1e-9);
    const SkeletonProximity before = distance.nearest(Point(-0.3, 0.4, 0));
    EXPECT_NEAR(before.distance, 0.5, 1e-9);
    EXPECT_NEAR(before.radius, 0.1, 1e-9);
}

TEST(SkeletonDistance, IsolatedNodesCountAndTheNearestOfSeveralWins) {
    SkeletonGraph g = taperedBone();
    g.nodes.push_back(Point(0.5, 3, 0));  // no bone
    g.radii.push_back(0.7);
    const SkeletonDistance distance(g);
    const SkeletonProximity nearNode = distance.nearest(Point(0.5, 2.5, 0));
    EXPECT_NEAR(nearNode.distance, 0.5, 1e-9);
    EXPECT_NEAR(nearNode.radius, 0.7, 1e-9);
    const SkeletonProximity nearBone = distance.nearest(Point(0.5, 1.0, 0));
    EXPECT_NEAR(nearBone.distance, 1.0, 1e-9);
    EXPECT_NEAR(nearBone.radius, 0.2, 1e-9);
}

TEST(SkeletonDistance, AGraphWithoutNodesOrRadiiIsACallerError) {
    EXPECT_THROW(SkeletonDistance{SkeletonGraph{}}, CallerError);
    SkeletonGraph noRadii = taperedBone();
    noRadii.radii.clear();
    EXPECT_THROW(SkeletonDistance{noRadii}, CallerError);
}

}  // namespace
}  // namespace pcskeleton
