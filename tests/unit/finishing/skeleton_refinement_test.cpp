// Refinement on hand-made graphs whose flaws are known, and on a clean ring.
#include <pcskeleton/finishing/skeleton_refinement.h>
#include "support/hand_made_graphs.h"
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace pcskeleton;
using namespace pcskeleton::graphs;

TEST(SkeletonRefinement, RemovesSpursCollapsesFalseLoopsAndMergesCloseJunctions) {
    SkeletonGraph g = straightChain();
    g.pointNode = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    const int spur = addNode(g, Point(0.2, 0.08, 0), 2);
    g.pointNode.push_back(spur);
    const int a = addNode(g, Point(0.5, 0.05, 0), 5);
    const int b = addNode(g, Point(0.55, 0.05, 0), a);
    const int c = addNode(g, Point(0.55, 0.0, 0.02), b);
    g.edges.push_back({5, c});
    // Two long limbs whose junctions (node 7 and a new node 0.03 away) nearly coincide.
    const int twin = addNode(g, Point(0.7, 0.03, 0), 7);
    int up = twin, down = twin;
    for (int step = 1; step <= 5; ++step) up = addNode(g, Point(0.7, 0.03 + 0.1 * step, 0), up);
    for (int step = 1; step <= 5; ++step) down = addNode(g, Point(0.7, 0.03, 0.1 * step), down);
    normalizeEdges(g.edges);
    ASSERT_EQ(invariantViolation(g), "");

    const RefinementReport report = refineSkeleton(g, {}, kSpacing);
    EXPECT_EQ(invariantViolation(g), "");
    EXPECT_EQ(report.spursRemoved, 1) << describe(report);
    EXPECT_EQ(report.cyclesCollapsed, 1) << describe(report);
    EXPECT_GE(report.junctionsMerged, 1) << describe(report);
    const SkeletonTopology t = analyseTopology(g);
    EXPECT_EQ(t.cycles, 0) << describe(t);
    EXPECT_EQ(t.tips, 4) << describe(t);  // the chain's two ends and the two limbs
    EXPECT_EQ(t.junctions, 1) << describe(t);
    // The spur's point now belongs to the node it sprouted from, which kept its place.
    const int spurPointNode = g.pointNode.back();
    ASSERT_GE(spurPointNode, 0);
    EXPECT_TRUE(g.nodes[spurPointNode].isApprox(Point(0.2, 0, 0)));
    // The node map follows every node: the spur to its junction, untouched ones to themselves.
    ASSERT_EQ(report.nodeMap.size(), std::size_t(down) + 1);
    EXPECT_EQ(report.nodeMap[spur], report.nodeMap[2]);
    EXPECT_TRUE(g.nodes[report.nodeMap[2]].isApprox(Point(0.2, 0, 0)));
    EXPECT_TRUE(g.nodes[report.nodeMap[10]].isApprox(Point(1.0, 0, 0)));
    EXPECT_EQ(report.nodeMap[a], report.nodeMap[c]) << "the false loop became one node";
    for (int node : report.nodeMap) EXPECT_TRUE(node >= 0 && node < int(g.nodeCount()));
}

TEST(SkeletonRefinement, TrimsStragglingEndsButNotThinLimbs) {
    // Each node of the chain owns 20 points; the straggling nodes own one each.
    SkeletonGraph g = straightChain();
    for (int node = 0; node <= 10; ++node) g.pointNode.insert(g.pointNode.end(), 20, node);
    auto ownOnePoint = [&](int node) { g.pointNode.push_back(node); return node; };
    // A hook of two one-point nodes bends the end of the chain sideways.
    const int hookStart = ownOnePoint(addNode(g, Point(1.05, 0.06, 0), 10));
    const int hookEnd = ownOnePoint(addNode(g, Point(1.02, 0.1, 0), hookStart));
    // A limb of one one-point node, too long to be a spur.
    const int stray = ownOnePoint(addNode(g, Point(0.5, 0.3, 0), 5));
    // A thin limb: one point per node too, four in all.
    int thin = 3;
    for (int step = 1; step <= 4; ++step) thin = ownOnePoint(addNode(g, Point(0.3, -0.1 * step, 0), thin));
    ASSERT_EQ(invariantViolation(g), "");
    ASSERT_EQ(analyseTopology(g).tips, 4);

    const RefinementReport report = refineSkeleton(g, {}, kSpacing);
    EXPECT_EQ(invariantViolation(g), "");
    EXPECT_EQ(report.endsTrimmed, 2) << describe(report);
    EXPECT_EQ(report.spursRemoved, 0) << describe(report);
    EXPECT_EQ(analyseTopology(g).tips, 3) << "the chain's ends and the thin limb";
    // The stragglers' points went to the node they hung from, which kept its place.
    EXPECT_EQ(report.nodeMap[hookEnd], report.nodeMap[10]);
    EXPECT_EQ(report.nodeMap[hookStart], report.nodeMap[10]);
    EXPECT_TRUE(g.nodes[report.nodeMap[10]].isApprox(Point(1.0, 0, 0)));
    EXPECT_EQ(report.nodeMap[stray], report.nodeMap[5]);
    EXPECT_NE(report.nodeMap[thin], report.nodeMap[3]) << "the thin limb stays";
}

TEST(SkeletonRefinement, TakesBackAnEndHookedOffItsLimbWithinTheTube) {
    // Noise gathers points at the side of a limb's end into nodes of their own, each owning
    // more than a straggler (8 points where the chain's nodes own 20), fewer in all than the
    // node they hang from: they turn off the limb's way within its tube (radius 0.2).
    const auto chainWithSidewaysEnd = [](const std::vector<double>& sideways, std::vector<int>& end,
                                         std::size_t pointsEach = 8) {
        SkeletonGraph g = straightChain();
        for (int node = 0; node <= 10; ++node) g.pointNode.insert(g.pointNode.end(), 20, node);
        int previous = 10;
        for (double y : sideways) {
            previous = addNode(g, Point(1.0, y, 0), previous);
            g.pointNode.insert(g.pointNode.end(), pointsEach, previous);
            end.push_back(previous);
        }
        return g;
    };
    for (const std::vector<double>& sideways : {std::vector<double>{0.15}, std::vector<double>{0.1, 0.18}}) {
        SCOPED_TRACE(std::to_string(sideways.size()) + " hooked nodes");
        std::vector<int> hook;
        SkeletonGraph hooked = chainWithSidewaysEnd(sideways, hook);
        ASSERT_EQ(invariantViolation(hooked), "");
        const RefinementReport report = refineSkeleton(hooked, {}, kSpacing);
        EXPECT_EQ(report.endsTrimmed, 1) << describe(report);
        for (int node : hook) EXPECT_EQ(report.nodeMap[node], report.nodeMap[10]);
        EXPECT_TRUE(hooked.nodes[report.nodeMap[10]].isApprox(Point(1.0, 0, 0)));
        EXPECT_EQ(analyseTopology(hooked).tips, 2);
    }

    // The same turn reaching out of the tube (past the radius plus a node spacing) is a
    // limb that bends, and stays.
    std::vector<int> bend;
    SkeletonGraph bent = chainWithSidewaysEnd({0.35}, bend);
    const RefinementReport kept = refineSkeleton(bent, {}, kSpacing);
    EXPECT_EQ(kept.endsTrimmed, 0) << describe(kept);
    EXPECT_NE(kept.nodeMap[bend[0]], kept.nodeMap[10]);
    EXPECT_EQ(bent.nodeCount(), std::size_t(12));

    // Within the tube but owning more points than the node it turns at: the limb's own end
    // (a thick body's cap past its last junction), which stays.
    std::vector<int> cap;
    SkeletonGraph capped = chainWithSidewaysEnd({0.15}, cap, 30);
    const RefinementReport capKept = refineSkeleton(capped, {}, kSpacing);
    EXPECT_EQ(capKept.endsTrimmed, 0) << describe(capKept);
    EXPECT_EQ(capped.nodeCount(), std::size_t(12));
}

namespace {

// A ring of 24 nodes, each owning 20 points, with a path of `pathNodes` nodes owning
// `pointsEach` points each across it, from node 0 to node 8.
SkeletonGraph ringWithPathAcross(int pathNodes, int pointsEach, std::vector<int>& path) {
    SkeletonGraph g = shapes::curveSkeleton(shapes::circle(Point::Zero(), 1.0, 24), 0.05);
    for (int node = 0; node < int(g.nodeCount()); ++node) g.pointNode.insert(g.pointNode.end(), 20, node);
    int previous = 0;
    for (int step = 1; step <= pathNodes; ++step) {
        const double t = double(step) / (pathNodes + 1);
        previous = addNode(g, (1 - t) * g.nodes[0] + t * g.nodes[8], previous);
        g.pointNode.insert(g.pointNode.end(), std::size_t(pointsEach), previous);
        path.push_back(previous);
    }
    g.edges.push_back({8, previous});
    normalizeEdges(g.edges);
    return g;
}

}  // namespace

TEST(SkeletonRefinement, CutsAStrayBridgeButNotAThinHandle) {
    // One node of one point joining two parts of the ring: points pulled into a gap.
    std::vector<int> stray;
    SkeletonGraph bridged = ringWithPathAcross(1, 1, stray);
    ASSERT_EQ(bridged.nodeCount(), 25u);
    ASSERT_EQ(invariantViolation(bridged), "");
    ASSERT_EQ(analyseTopology(bridged).cycles, 2);
    const RefinementReport report = refineSkeleton(bridged, {}, kSpacing);
    EXPECT_EQ(invariantViolation(bridged), "");
    EXPECT_EQ(report.bridgesCut, 1) << describe(report);
    EXPECT_NE(describe(report).find(", 1 stray bridge,"), std::string::npos) << describe(report);
    EXPECT_EQ(analyseTopology(bridged).cycles, 1);
    EXPECT_EQ(analyseTopology(bridged).tips, 0) << "the bridge's node went to the junction it hung from";
    EXPECT_EQ(report.nodeMap[stray[0]], report.nodeMap[0]);
    EXPECT_TRUE(bridged.nodes[report.nodeMap[0]].isApprox(Point(1, 0, 0))) << "the junction keeps its place";

    // A thin handle: one point per node too, but four in all (a fifth of the median node's).
    std::vector<int> thin;
    SkeletonGraph handle = ringWithPathAcross(4, 1, thin);
    const RefinementReport kept = refineSkeleton(handle, {}, kSpacing);
    EXPECT_EQ(kept.bridgesCut, 0) << describe(kept);
    EXPECT_EQ(analyseTopology(handle).cycles, 2);
}

namespace {

// Two parallel chains of 11 nodes (20 points each, radius 0.2), along x at y = 0 and at
// y = 0.5, and a node of `bridgePoints` points half way between their nodes `at`.
SkeletonGraph chainsSideBySide(int bridgePoints, int at = 5) {
    SkeletonGraph g = straightChain();
    for (int i = 0; i <= 10; ++i) {  // nodes 11..21; node 11 + i faces node i
        g.nodes.emplace_back(kSpacing * i, 0.5, 0);
        g.radii.push_back(0.2);
        if (i > 0) g.edges.push_back({10 + i, 11 + i});
    }
    for (int node = 0; node < int(g.nodeCount()); ++node) g.pointNode.insert(g.pointNode.end(), 20, node);
    const int bridge = addNode(g, Point(kSpacing * at, 0.25, 0), at);
    g.edges.push_back({bridge, 11 + at});
    normalizeEdges(g.edges);
    g.pointNode.insert(g.pointNode.end(), std::size_t(bridgePoints), bridge);
    return g;
}

}  // namespace

TEST(SkeletonRefinement, PartsSideBySideJoinedByAStrayBridgeComeApart) {
    // Two parts side by side (two close tubes under noise) joined by a one-point node,
    // between their middles or between their ends (a U): the node is cut away, and the
    // skeleton has two parts.
    for (const int at : {5, 0}) {
        SkeletonGraph joined = chainsSideBySide(1, at);
        ASSERT_EQ(invariantViolation(joined), "");
        ASSERT_EQ(analyseTopology(joined).components, 1);
        const RefinementReport report = refineSkeleton(joined, {}, kSpacing);
        EXPECT_EQ(invariantViolation(joined), "") << at;
        EXPECT_EQ(report.bridgesCut, 1) << at << ": " << describe(report);
        EXPECT_EQ(analyseTopology(joined).components, 2) << at << ": " << describe(analyseTopology(joined));
        EXPECT_EQ(analyseTopology(joined).tips, 4) << at << ": " << describe(analyseTopology(joined));
    }

    // Kept: connections with points of their own (a real one, however thin; a real U); a
    // one-point node where a limb ends at the side of the other part, not two parts running
    // side by side (the upper chain's nodes 6-10 turn away, 90 degrees); and a node of one
    // point on a straight chain (a thin stretch: the chain runs on both ways, not the same).
    SkeletonGraph elbow = chainsSideBySide(1);
    for (int i = 17; i <= 21; ++i) elbow.nodes[i] = Point(0.5, 0.5 + kSpacing * (i - 16), 0);
    SkeletonGraph straight = straightChain();
    for (int node = 0; node <= 10; ++node) {
        straight.pointNode.insert(straight.pointNode.end(), node == 5 ? 1 : 20, node);
    }
    for (SkeletonGraph kept : {chainsSideBySide(5), chainsSideBySide(5, 0), elbow, straight}) {
        EXPECT_EQ(refineSkeleton(kept, {}, kSpacing).bridgesCut, 0);
        EXPECT_EQ(analyseTopology(kept).components, 1);
    }
}

namespace {

// A ring of 24 nodes of radius 0.05 and radius 1, and one bone straight from node 0 to
// node 8 (1.73 long), whose two ends have radius `endRadius`; with `limbAtNode0`, a limb
// of 5 nodes runs out from node 0, a junction of four bones.
SkeletonGraph ringWithBoneAcross(double endRadius, bool limbAtNode0 = false) {
    SkeletonGraph g = shapes::curveSkeleton(shapes::circle(Point::Zero(), 1.0, 24), 0.05);
    g.radii[0] = g.radii[8] = endRadius;
    g.edges.push_back({0, 8});
    normalizeEdges(g.edges);
    for (int step = 1, previous = 0; limbAtNode0 && step <= 5; ++step) {
        previous = addNode(g, Point(1.0 + 0.2 * step, 0, 0), previous);
    }
    return g;
}

}  // namespace

TEST(SkeletonRefinement, CutsABoneAcrossAGapButNotARealBar) {
    // The strands' tubes (radius 0.6) do not meet along the bone: 1.73 > 1.15 x 1.2 (its
    // stretch is 1.73 / 1.2 = 1.44). Also where a limb leaves one of its ends.
    for (const bool limb : {false, true}) {
        SkeletonGraph gap = ringWithBoneAcross(0.6, limb);
        ASSERT_EQ(analyseTopology(gap).cycles, 2);
        const RefinementReport report = refineSkeleton(gap, {}, kSpacing);
        EXPECT_EQ(report.bridgesCut, 1) << limb << ": " << describe(report);
        EXPECT_EQ(analyseTopology(gap).cycles, 1) << limb << ": " << describe(analyseTopology(gap));
        EXPECT_EQ(analyseTopology(gap).tips, limb ? 1 : 0) << limb << ": " << describe(analyseTopology(gap));
    }

    // Kept: tubes of radius 0.8 meet along it (1.73 < 1.15 x 1.6), a bar; tubes of radius
    // 0.04, thinner than the node spacing, are not judged (every bone is longer than them);
    // a gap stretch of 0 cuts none, and one of 1.5, above the bone's, neither.
    const std::vector<std::pair<double, double>> kept{{0.8, 1.15}, {0.04, 1.15}, {0.6, 0.0}, {0.6, 1.5}};
    for (const auto& [endRadius, stretch] : kept) {
        SkeletonGraph g = ringWithBoneAcross(endRadius);
        RefinementLimits limits;
        limits.gapStretch = stretch;
        EXPECT_EQ(refineSkeleton(g, {}, kSpacing, limits).bridgesCut, 0) << endRadius << ", " << stretch;
        EXPECT_EQ(analyseTopology(g).cycles, 2) << endRadius << ", " << stretch;
    }
}

TEST(SkeletonRefinement, LeavesACleanSkeletonAlone) {
    SkeletonGraph ring = shapes::curveSkeleton(shapes::circle(Point::Zero(), 1.0, 24), 0.3);
    const SkeletonGraph before = ring;
    EXPECT_FALSE(refineSkeleton(ring, {}, kSpacing).changedAnything());
    EXPECT_EQ(ring.edges, before.edges);
}

namespace {

// Eight nodes of radius 0.1 on a circle of radius 0.18 (an opening of 0.08, narrower than
// the tube) with a wide step between nodes 0 and 1: their balls just touch.
SkeletonGraph narrowLoop() {
    SkeletonGraph g;
    const double pi = std::acos(-1.0), wide = 2 * std::asin(0.1 / 0.18), narrow = (2 * pi - wide) / 7;
    for (int i = 0; i < 8; ++i) {
        const double angle = i == 0 ? 0.0 : wide + (i - 1) * narrow;
        g.nodes.emplace_back(0.18 * std::cos(angle), 0.18 * std::sin(angle), 0.0);
        g.radii.push_back(0.1);
        g.edges.push_back({i, (i + 1) % 8});
    }
    normalizeEdges(g.edges);
    return g;
}

// The narrow loop with the surface of tubes of radius 0.1 along its bones, each point
// attached to its nearest node. Without the bone 0-1 when `touching`: then the ends at
// nodes 0 and 1 are two round caps that touch.
struct LoopWithPoints {
    SkeletonGraph graph = narrowLoop();
    PointList points;
};

LoopWithPoints narrowLoopWithPoints(bool touching) {
    LoopWithPoints loop;
    SkeletonGraph& g = loop.graph;
    shapes::Polyline bones;
    for (const Edge& e : g.edges) {
        if (touching && e == Edge{0, 1}) continue;
        bones.push_back({g.nodes[e[0]], g.nodes[e[1]]});
    }
    loop.points = shapes::tube(bones, 0.1, 4000);
    giveEachPointItsNearestNode(g, loop.points);
    return loop;
}

}  // namespace

TEST(SkeletonRefinement, OpensANarrowLoopWherePartsTouch) {
    auto [g, points] = narrowLoopWithPoints(true);
    const RefinementReport report = refineSkeleton(g, points, kSpacing);
    EXPECT_EQ(report.cyclesCut, 1) << describe(report);
    EXPECT_EQ(invariantViolation(g), "");
    const SkeletonTopology t = analyseTopology(g);
    EXPECT_EQ(t.cycles, 0) << describe(t);
    EXPECT_EQ(t.components, 1) << describe(t);
    EXPECT_EQ(t.tips, 2) << describe(t);  // the two ends that touched
    EXPECT_EQ(g.nodes[report.nodeMap[0]], narrowLoop().nodes[0]) << "the contact's nodes keep their place";
    EXPECT_NE(describe(report).find("cut 1 narrow loop"), std::string::npos) << describe(report);
}

// The hole is 0.16 across, 1.6 node spacings: not a contact, but narrower than the hole
// test's two node spacings across (RefinementLimits::minHole), where gaps between samples
// fill loops as wide on the robustness suite. The test opens it as a loop over data unless
// told that smaller holes are real.
TEST(SkeletonRefinement, KeepsANarrowHoleTheSurfaceGoesRound) {
    auto [g, points] = narrowLoopWithPoints(false);
    RefinementLimits smallHolesToo;
    smallHolesToo.minHole = 0.5;
    const RefinementReport report = refineSkeleton(g, points, kSpacing, smallHolesToo);
    EXPECT_EQ(report.cyclesCut + report.filledLoopsCut, 0) << describe(report);
    EXPECT_EQ(analyseTopology(g).cycles, 1);

    auto [atDefaults, samePoints] = narrowLoopWithPoints(false);
    const RefinementReport opened = refineSkeleton(atDefaults, samePoints, kSpacing);
    EXPECT_EQ(opened.cyclesCut, 0) << describe(opened);
    EXPECT_EQ(opened.filledLoopsCut, 1) << describe(opened);
}

TEST(SkeletonRefinement, NoLoopIsOpenedWithAnOpeningAndAHoleOfZero) {
    auto [g, points] = narrowLoopWithPoints(true);
    RefinementLimits none;
    none.minOpening = 0.0;
    none.minHole = 0.0;
    const RefinementReport report = refineSkeleton(g, points, kSpacing, none);
    EXPECT_EQ(report.cyclesCut + report.filledLoopsCut, 0) << describe(report);
    EXPECT_EQ(analyseTopology(g).cycles, 1);
}
