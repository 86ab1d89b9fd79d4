// Re-centring: nodes of a half tube (one view) move onto its axis; nodes whose points
// surround them stay at their centre; so do nodes of a curled sheet, whose curl changes
// along it as a leaf's does, or that is folded along its midrib.
#include <pcskeleton/finishing/node_recentering.h>
#include <pcskeleton/curve_skeleton.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace pcskeleton {
namespace {

// Three nodes along x, each at the centroid of its 40 points; `across(n, k)` gives the
// (y, z) of node n's k-th point.
SkeletonGraph threeNodesAlongX(const std::function<Eigen::Vector2d(int, int)>& across, PointList& points) {
    SkeletonGraph g;
    for (int n = 0; n < 3; ++n) {
        Point centroid = Point::Zero();
        for (int k = 0; k < 40; ++k) {
            const Eigen::Vector2d q = across(n, k);
            points.emplace_back(n + 0.01 * (k % 5), q.x(), q.y());
            g.pointNode.push_back(n);
            centroid += points.back();
        }
        g.nodes.push_back(centroid / 40);
        g.radii.push_back(0.1);
    }
    g.edges = {{0, 1}, {1, 2}};
    return g;
}

// Cross-sections around the x axis covering `sweep` radians of circles of the given radii
// (a tube of radius 0.2 by default).
SkeletonGraph nodesOfAnArc(double sweep, PointList& points, const std::vector<double>& radii = {0.2, 0.2, 0.2}) {
    return threeNodesAlongX(
        [&](int n, int k) {
            const double angle = sweep * (k + 0.5) / 40;
            return Eigen::Vector2d(radii[n] * std::cos(angle), radii[n] * std::sin(angle));
        },
        points);
}

// A leaf folded along its midrib (the x axis): two flat wings of width 0.2, `opening`
// radians apart, the same at every node.
SkeletonGraph nodesOfAFold(double opening, PointList& points) {
    return threeNodesAlongX(
        [&](int, int k) {
            const double along = 0.2 * ((k / 2) + 0.5) / 20, side = k % 2 ? 1.0 : -1.0;
            return Eigen::Vector2d(side * along * std::sin(opening / 2), along * std::cos(opening / 2));
        },
        points);
}

// Three nodes on arcs of a third of a circle with the given radii, each alone a tube's
// wall: none moves, all three are counted as left in place for their neighbours.
void expectCurledSheetLeftInPlace(const std::vector<double>& radii) {
    PointList points;
    SkeletonGraph g = nodesOfAnArc(2.0, points, radii);
    const SkeletonGraph before = g;
    const RecenteringReport report = recentreOneSidedNodes(g, points, DataSupport(points, 1.0));
    EXPECT_EQ(report.recentredNodes, 0);
    EXPECT_EQ(report.unlikeNeighbours, 3);
    EXPECT_EQ(g.nodes, before.nodes);
}

TEST(NodeRecentering, NodesOfAHalfTubeMoveOntoItsAxisWithItsRadius) {
    PointList points;
    SkeletonGraph g = nodesOfAnArc(M_PI, points);
    ASSERT_GT(std::hypot(g.nodes[1].y(), g.nodes[1].z()), 0.1) << "the centroid lies on the visible wall";
    const RecenteringReport report = recentreOneSidedNodes(g, points, DataSupport(points, 1.0));
    EXPECT_EQ(report.recentredNodes, 3);
    for (std::size_t n = 0; n < 3; ++n) {
        EXPECT_NEAR(std::hypot(g.nodes[n].y(), g.nodes[n].z()), 0.0, 1e-6) << "node " << n;
        EXPECT_NEAR(g.radii[n], 0.2, 1e-6);
    }
}

TEST(NodeRecentering, NodesSurroundedByTheirPointsStay) {
    PointList points;
    SkeletonGraph g = nodesOfAnArc(2 * M_PI, points);
    const SkeletonGraph before = g;
    EXPECT_EQ(recentreOneSidedNodes(g, points, DataSupport(points, 1.0)).recentredNodes, 0);
    EXPECT_EQ(g.nodes, before.nodes);
    EXPECT_EQ(g.radii, before.radii);
}

TEST(NodeRecentering, ACurledSheetWhoseCurlChangesStaysOnTheSheet) {
    // A leaf curled across its width, a third of a circle, more tightly from node to node:
    // each cross-section alone looks like a tube's wall, the circles of neighbours disagree.
    expectCurledSheetLeftInPlace({0.2, 0.3, 0.45});

    // The same arcs with one radius are a tube seen from one side: all three move.
    PointList tube;
    SkeletonGraph t = nodesOfAnArc(2.0, tube, {0.3, 0.3, 0.3});
    EXPECT_EQ(recentreOneSidedNodes(t, tube, DataSupport(tube, 1.0)).recentredNodes, 3);
}

TEST(NodeRecentering, TwoCirclesThatAgreeByChanceOnACurledSheetDoNotMoveTheNode) {
    // The curl tightens unevenly (as the tobacco leaf's tip): the last two circles agree,
    // but the middle one disagrees with the first, so it is no tube to confirm the last.
    expectCurledSheetLeftInPlace({0.2, 0.3, 0.34});
}

TEST(NodeRecentering, ALeafFoldedAlongItsMidribStaysOnTheLeaf) {
    // A V of two straight wings 120 degrees apart, as a corn leaf's cross-section: each fits
    // a circle over a third of it, and the neighbours' circles agree, as a tube's wall's do;
    // but each half of the arc is straight, where a tube's curves as the whole does.
    PointList points;
    SkeletonGraph g = nodesOfAFold(2 * M_PI / 3, points);
    const SkeletonGraph before = g;
    const RecenteringReport report = recentreOneSidedNodes(g, points, DataSupport(points, 1.0));
    EXPECT_EQ(report.recentredNodes, 0);
    EXPECT_EQ(report.foldedSheets, 3);
    EXPECT_EQ(g.nodes, before.nodes);
}

TEST(NodeRecentering, AWallNodeNoNeighbourConfirmsStays) {
    // One node of arc points between two ends with no points of their own: nothing around
    // it shows a tube, so its circle's centre is a guess and it stays.
    PointList points;
    SkeletonGraph g = nodesOfAnArc(M_PI, points);
    for (int& node : g.pointNode) node = node == 1 ? 1 : -1;
    EXPECT_EQ(recentreOneSidedNodes(g, points, DataSupport(points, 1.0)).recentredNodes, 0);
}

TEST(NodeRecentering, AOneViewScanOfATubeGivesItsAxis) {
    // The half of an open tube facing +y, as one scan sees it.
    PointList half;
    for (const Point& p : shapes::cylinder(8000, 0.1, 1.0, false)) {
        if (p.y() > 0) half.push_back(p);
    }
    const double diagonal = boundingBox(half).diagonal().norm();
    // Along the tube (its ends, where the scan's two edges meet, are not a cross-section).
    auto meanAxisDistance = [&](const SkeletonGraph& s) {
        const std::vector<int> degree = nodeDegrees(s.nodeCount(), s.edges);
        double sum = 0;
        int along = 0;
        for (std::size_t n = 0; n < s.nodeCount(); ++n) {
            if (degree[n] != 2 || s.nodes[n].z() < 0.1 || s.nodes[n].z() > 0.9) continue;
            sum += std::hypot(s.nodes[n].x(), s.nodes[n].y());
            ++along;
        }
        EXPECT_GT(along, 8);
        return sum / along / diagonal;
    };
    SkeletonParameters off;
    off.graph.recentre = false;
    const SkeletonResult centroids = computeCurveSkeleton(half, off);
    const SkeletonResult recentred = computeCurveSkeleton(half);
    EXPECT_GT(meanAxisDistance(centroids.skeleton), 0.04) << "the paper's nodes sit on the visible wall";
    EXPECT_LT(meanAxisDistance(recentred.skeleton), 0.02);
    ASSERT_TRUE(recentred.quality.recentering);
    EXPECT_GT(recentred.quality.recentering->recentredNodes, 0);
    EXPECT_EQ(recentred.quality.topology.components, 1);
    EXPECT_TRUE(recentred.quality.nodesOutside.empty()) << "a re-centred node is not outside the shape";
}

}  // namespace
}  // namespace pcskeleton
