// Step 4 alone: farthest-point sampling, connection through the 1-rings, collapse of
// the triangles.
#include <pcskeleton/skeleton/skeleton_thinning.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace pcskeleton;

TEST(Thinning, FarthestPointSamplingCoversEveryPointWithinTheRadius) {
    const PointList points = shapes::sphere(3000, 1.0, 3);
    const double radius = 0.3;
    const SampledPoints s = farthestPointSampling(points, radius);
    ASSERT_EQ(s.owner.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double d = (points[i] - points[s.samples[s.owner[i]]]).norm();
        EXPECT_LE(d, radius);
        // The owner is the nearest sample.
        for (int sample : s.samples) ASSERT_LE(d, (points[i] - points[sample]).norm() + 1e-12);
    }
    // Samples are farther apart than the radius.
    for (std::size_t a = 0; a < s.samples.size(); ++a)
        for (std::size_t b = a + 1; b < s.samples.size(); ++b)
            EXPECT_GT((points[s.samples[a]] - points[s.samples[b]]).norm(), radius);
}

TEST(Thinning, CollapseRemovesTrianglesButKeepsLongerCycles) {
    // A square (a 4-cycle) with a fan of triangles hanging off one corner.
    ThinnedGraph g;
    g.nodes = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(-0.3, -0.2, 0),
               Point(-0.2, -0.4, 0)};
    g.edges = {{0, 1}, {1, 2}, {2, 3}, {0, 3}, {0, 4}, {0, 5}, {4, 5}};
    g.owner = {0, 1, 2, 3, 4, 5};
    collapseTriangles(g);
    const SkeletonTopology t = analyseTopology(g.nodes.size(), g.edges);
    EXPECT_EQ(t.cycles, 1) << describe(t);
    EXPECT_EQ(t.nodes, 5) << describe(t);
    EXPECT_EQ(g.owner[4], g.owner[5]) << "the collapsed edge's points merge";
}

TEST(Thinning, ConnectionsFollowOneRings) {
    const PointList points = shapes::cylinder(2000, 0.1, 1.0, false);
    const OneRings rings = OneRings::compute(points, 10);
    std::vector<int> owner(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) owner[i] = points[i].z() < 0.5 ? 0 : 1;
    const std::vector<Edge> edges = connectByOneRings(rings, owner, points, points, std::numeric_limits<double>::infinity());
    ASSERT_EQ(edges.size(), 1u);
    EXPECT_EQ(edges[0], (Edge{0, 1}));
}

TEST(Thinning, StretchedLinksConnectOnlyWhatNothingElseConnects) {
    // A tube cut lengthwise into three 120-degree sectors: each sector's points are 1-ring
    // neighbours of both others', so the three samples form a triangle.
    const PointList points = shapes::cylinder(3000, 0.1, 1.0, false);
    const OneRings rings = OneRings::compute(points, 10);
    std::vector<int> owner(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double angle = std::atan2(points[i].y(), points[i].x()) + M_PI;  // 0 .. 2 pi
        owner[i] = std::min(2, int(angle / (2.0 * M_PI / 3.0)));
    }
    const double infinity = std::numeric_limits<double>::infinity();
    EXPECT_EQ(connectByOneRings(rings, owner, points, points, infinity).size(), 3u) << "the paper's rule: a triangle";

    // "Contraction" pulls sector 2 far away: its links to sectors 0 and 1 are stretched.
    PointList contracted = points;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (owner[i] == 2) contracted[i] += Point(5.0, 0, 0);
    }
    const std::vector<Edge> limited = connectByOneRings(rings, owner, points, contracted, 1.0);
    ASSERT_EQ(limited.size(), 2u) << "one stretched link keeps sector 2 connected, the other would close a cycle";
    EXPECT_TRUE(hasEdge(limited, 0, 1));
    EXPECT_EQ(analyseTopology(3, limited).components, 1);
    EXPECT_EQ(analyseTopology(3, limited).cycles, 0);
    EXPECT_EQ(connectByOneRings(rings, owner, points, contracted, infinity).size(), 3u);
}
