// Gap bridging on hand-made pieces, and through the whole pipeline on a tube with a band of
// missing data.
#include <pcskeleton/finishing/gap_bridging.h>
#include <pcskeleton/curve_skeleton.h>
#include "support/hand_made_graphs.h"
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace pcskeleton;
using namespace pcskeleton::graphs;

namespace {

// A chain along x from `from` in `count` steps of kSpacing, at height y; returns its first node.
int addChain(SkeletonGraph& g, double from, int count, double y = 0.0) {
    const int first = int(g.nodeCount());
    for (int i = 0; i < count; ++i) {
        g.nodes.emplace_back(from + kSpacing * i, y, 0);
        g.radii.push_back(0.05);
        if (i > 0) g.edges.push_back({first + i - 1, first + i});
    }
    return first;
}

// Two collinear pieces along x, nodes 0-4 (x 0..0.4) and 5-9 (x 0.7..1.1): a gap of 3 spacings.
SkeletonGraph brokenChain() {
    SkeletonGraph g;
    addChain(g, 0.0, 5);
    addChain(g, 0.7, 5);
    normalizeEdges(g.edges);
    return g;
}

PointList withoutSlab(const PointList& points, double fromZ, double toZ) {
    PointList kept;
    std::copy_if(points.begin(), points.end(), std::back_inserter(kept),
                 [&](const Point& p) { return p.z() < fromZ || p.z() > toZ; });
    return kept;
}

}  // namespace

TEST(GapBridging, CollinearPiecesAcrossAGapAreJoinedTipToTip) {
    SkeletonGraph g = brokenChain();
    const GapBridgingReport report = bridgeGaps(g, kSpacing, 8.0);
    ASSERT_EQ(report.bridges.size(), 1u) << describe(report);
    EXPECT_EQ(report.bridges[0], (Edge{4, 5}));
    EXPECT_NEAR(report.bridgeLengths[0], 0.3, 1e-12);
    EXPECT_EQ(invariantViolation(g), "");
    const SkeletonTopology t = analyseTopology(g);
    EXPECT_EQ(t.components, 1) << describe(t);
    EXPECT_EQ(t.cycles, 0) << describe(t);  // both tips point at the other piece: one bridge only
    EXPECT_EQ(describe(report), "1 bridged, 0.3 long");
}

TEST(GapBridging, GapsLongerThanTheLimitAndALimitOfZeroBridgeNothing) {
    // The tubes' walls (radius half a spacing) are 2.5 spacings apart.
    for (double limit : {2.4, 0.0}) {
        SkeletonGraph g = brokenChain();
        const GapBridgingReport report = bridgeGaps(g, kSpacing, limit);
        EXPECT_TRUE(report.bridges.empty()) << limit;
        EXPECT_EQ(analyseTopology(g).components, 2) << limit;
        EXPECT_EQ(describe(report), "none bridged");
    }
}

TEST(GapBridging, PiecesSideBySideStayApart) {
    // Two parallel chains 2 spacings apart: each tip points along its own chain.
    SkeletonGraph g;
    addChain(g, 0.0, 8);
    addChain(g, 0.0, 8, 2 * kSpacing);
    normalizeEdges(g.edges);
    EXPECT_TRUE(bridgeGaps(g, kSpacing, 8.0).bridges.empty());
    EXPECT_EQ(analyseTopology(g).components, 2);
}

TEST(GapBridging, AHookAtTheEndOfALimbDoesNotTurnItTowardsAPieceBesideIt) {
    // Two parallel chains 3 spacings apart, as two close tubes scanned from the side: the
    // first one's end, a half cap, contracted into a hook of two short bones curling
    // towards the second chain. Over its last three bones the limb points at the second
    // chain's end; the limb as a whole points along the chains.
    SkeletonGraph g;
    addChain(g, 0.0, 8);  // nodes 0-7, x 0..0.7
    for (const Point& hook : {Point(0.76, 0.07, 0), Point(0.78, 0.15, 0)}) {
        g.nodes.push_back(hook);
        g.radii.push_back(0.05);
        g.edges.push_back({int(g.nodeCount()) - 2, int(g.nodeCount()) - 1});
    }
    addChain(g, 0.0, 9, 3 * kSpacing);  // x 0..0.8
    normalizeEdges(g.edges);
    const GapBridgingReport report = bridgeGaps(g, kSpacing, 8.0);
    EXPECT_TRUE(report.bridges.empty()) << describe(report);
    EXPECT_EQ(analyseTopology(g).components, 2);
}

TEST(GapBridging, ALimbThatTurnsIntoAnotherEndsAtTheCornerAndLooksAheadFromIt) {
    // Piece A: a chain along +x to node 4 at x 0.4, which turns there by `turn` degrees into
    // a second chain of 5 bones (a stem that turns into a leaf where its top is hidden).
    // Piece B: a chain along y at x 1.0, 5.5 spacings from node 4's tube. Neither piece has
    // a tip pointing at the other; A's corner points at B when the turn is sharp.
    for (const double turn : {90.0, 40.0}) {
        SkeletonGraph g;
        addChain(g, 0.0, 5);
        const double angle = turn * M_PI / 180.0;
        for (int i = 1; i <= 5; ++i) {
            g.nodes.emplace_back(0.4 + kSpacing * i * std::cos(angle), kSpacing * i * std::sin(angle), 0);
            g.radii.push_back(0.05);
            g.edges.push_back({i == 1 ? 4 : int(g.nodeCount()) - 2, int(g.nodeCount()) - 1});
        }
        const int across = int(g.nodeCount());
        for (int i = 0; i < 5; ++i) {
            g.nodes.emplace_back(1.0, kSpacing * (i - 2), 0);
            g.radii.push_back(0.05);
            if (i > 0) g.edges.push_back({across + i - 1, across + i});
        }
        normalizeEdges(g.edges);
        const GapBridgingReport report = bridgeGaps(g, kSpacing, 8.0);
        if (turn == 90.0) {
            ASSERT_EQ(report.bridges.size(), 1u) << describe(report);
            EXPECT_EQ(report.bridges[0], (Edge{4, across + 2}));
            EXPECT_EQ(analyseTopology(g).components, 1);
        } else {
            EXPECT_TRUE(report.bridges.empty()) << "a limb that bends by 40 degrees goes on: " << describe(report);
            EXPECT_EQ(analyseTopology(g).components, 2);
        }
    }
}

TEST(GapBridging, JoinsTheNearestNodeAheadNotTheNearestNode) {
    // Piece B: a node just beside the tip (outside the cone), and a chain straight ahead.
    SkeletonGraph g;
    addChain(g, 0.0, 5);                        // tip: node 4 at x 0.4, pointing along +x
    const int ahead = addChain(g, 0.8, 3);      // nodes 5-7, 4 spacings ahead
    g.nodes.emplace_back(0.4, 0.25, 0);         // node 8, 2.5 spacings to the side
    g.radii.push_back(0.05);
    g.edges.push_back({7, 8});
    normalizeEdges(g.edges);
    const GapBridgingReport report = bridgeGaps(g, kSpacing, 8.0);
    ASSERT_EQ(report.bridges.size(), 1u) << describe(report);
    EXPECT_EQ(report.bridges[0], (Edge{4, ahead}));
}

TEST(GapBridging, TubeWithABandOfMissingDataGivesOneSkeleton) {
    // A tube of radius 0.1 and length 2 with no points for 0.9 < z < 1.1: the gap is about
    // 5 node spacings long.
    const PointList cloud = withoutSlab(shapes::cylinder(8000, 0.1, 2.0, /*capped=*/true), 0.9, 1.1);
    const SkeletonResult bridged = computeCurveSkeleton(cloud);
    const SkeletonTopology t = analyseTopology(bridged.skeleton);
    EXPECT_EQ(t.components, 1) << describe(t);
    EXPECT_EQ(t.tips, 2) << describe(t);
    EXPECT_EQ(t.cycles, 0) << describe(t);
    ASSERT_TRUE(bridged.quality.gapBridging);
    ASSERT_EQ(bridged.quality.gapBridging->bridges.size(), 1u);
    EXPECT_EQ(bridged.skeleton.inferred, bridged.quality.gapBridging->bridges) << "the bridge is marked as guessed";
    const std::vector<char> flags = inferredFlags(bridged.skeleton);
    EXPECT_EQ(std::count(flags.begin(), flags.end(), 1), 1);
    for (int end : bridged.quality.gapBridging->bridges[0]) {
        const Point& node = bridged.skeleton.nodes[std::size_t(end)];
        EXPECT_LT(std::hypot(node.x(), node.y()), 0.03) << node.transpose();  // on the axis
    }

    SkeletonParameters paper;
    paper.graph.gapLimit = 0;
    EXPECT_EQ(analyseTopology(computeCurveSkeleton(cloud, paper).skeleton).components, 2);
}

TEST(GapBridging, AYSeenFromAboveWithAStretchOfOneArmHiddenIsOnePieceWithTheGuessMarked) {
    // A Y of tubes (radius 0.05) lying in the xy plane, scanned from above, with nothing seen
    // of one arm for 0.35 < x < 0.5 (something in front of it): the arm's far end is a piece
    // of its own until the gap is bridged.
    const shapes::Polyline y = {{Point(0, -0.6, 0), Point(0, 0, 0)},
                                {Point(0, 0, 0), Point(0.6, 0.35, 0)},
                                {Point(0, 0, 0), Point(-0.6, 0.35, 0)}};
    PointList cloud;
    for (const Point& p : shapes::visibleFrom(shapes::tube(y, 0.05, 24000), Point(0, 0, -1), 0.015)) {
        if (p.x() < 0.35 || p.x() > 0.5) cloud.push_back(p);
    }
    const SkeletonResult result = computeCurveSkeleton(cloud);
    const SkeletonTopology t = analyseTopology(result.skeleton);
    EXPECT_EQ(t.components, 1) << describe(t);
    EXPECT_EQ(t.cycles, 0) << describe(t);
    // Three tips, or one more: the scan's edge across the hidden stretch can leave a short
    // prong beside the bridge (the measure allows one tip either way).
    EXPECT_GE(t.tips, 3) << describe(t);
    EXPECT_LE(t.tips, 4) << describe(t);
    ASSERT_EQ(result.skeleton.inferred.size(), 1u);
    const Edge bridge = result.skeleton.inferred[0];
    const double x0 = result.skeleton.nodes[std::size_t(bridge[0])].x();
    const double x1 = result.skeleton.nodes[std::size_t(bridge[1])].x();
    EXPECT_LT(std::min(x0, x1), 0.37) << "the bridge crosses the hidden stretch";
    EXPECT_GT(std::max(x0, x1), 0.48) << "the bridge crosses the hidden stretch";

    SkeletonParameters noBridges;
    noBridges.graph.gapLimit = 0;
    EXPECT_EQ(analyseTopology(computeCurveSkeleton(cloud, noBridges).skeleton).components, 2);
}

TEST(GapBridging, TwoSeparateParallelTubesStayTwoSkeletons) {
    const shapes::Polyline twoTubes = {{Point(0, 0, 0), Point(0, 0, 1)}, {Point(0.3, 0, 0), Point(0.3, 0, 1)}};
    const SkeletonResult result = computeCurveSkeleton(shapes::tube(twoTubes, 0.1, 8000));
    EXPECT_EQ(analyseTopology(result.skeleton).components, 2);
    ASSERT_TRUE(result.quality.gapBridging);
    EXPECT_TRUE(result.quality.gapBridging->bridges.empty());
}

TEST(GapBridging, ANegativeOrInfiniteLimitIsRefused) {
    SkeletonParameters p;
    for (double bad : {-1.0, std::numeric_limits<double>::infinity()}) {
        p.graph.gapLimit = bad;
        EXPECT_THROW(checkSkeletonGraphParameters(p.graph), InvalidInput) << bad;
    }
}

TEST(GapBridging, TheGapEndsAtTheOtherPiecesWallNotAtItsAxis) {
    // A thin chain pointing along +x at a thick node 9 spacings ahead of its tip, whose tube
    // (radius 3 spacings) comes within 6 spacings of it: a gap of 6, inside the limit of 8.
    for (const double thickRadius : {3 * kSpacing, 0.5 * kSpacing}) {
        SkeletonGraph g;
        addChain(g, 0.0, 5);  // tip: node 4 at x 0.4
        const int thick = addChain(g, 0.4 + 9 * kSpacing, 1);
        addChain(g, 0.4 + 9 * kSpacing, 1, kSpacing);  // a bone across, so that no node is alone
        g.edges.push_back({thick, thick + 1});
        g.radii[std::size_t(thick)] = thickRadius;
        normalizeEdges(g.edges);
        const GapBridgingReport report = bridgeGaps(g, kSpacing, 8.0);
        if (thickRadius > kSpacing) {
            ASSERT_EQ(report.bridges.size(), 1u) << describe(report);
            EXPECT_EQ(report.bridges[0], (Edge{4, thick}));
            EXPECT_NEAR(report.bridgeLengths[0], 9 * kSpacing, 1e-12) << "the bone still ends on the axis";
        } else {
            EXPECT_TRUE(report.bridges.empty()) << "a thin piece's wall is 8.5 spacings away";
        }
    }
}

TEST(GapBridging, ALoneNodeJoinsTheNearestPieceWithinTheLimitAndNoFarther) {
    // A chain along x and one node without a bone below its middle (a foot whose leg is
    // hidden): joined across a gap of 5 spacings between the tubes, not across one of 12.
    for (const double below : {6.0, 13.0}) {
        SkeletonGraph g;
        addChain(g, 0.0, 9);  // nodes 0-8, radius half a spacing
        g.nodes.emplace_back(4 * kSpacing, -below * kSpacing, 0);  // node 9
        g.radii.push_back(0.5 * kSpacing);
        normalizeEdges(g.edges);
        const GapBridgingReport report = bridgeGaps(g, kSpacing, 8.0);
        if (below < 8) {
            ASSERT_EQ(report.bridges.size(), 1u) << describe(report);
            EXPECT_EQ(report.bridges[0], (Edge{4, 9}));
            EXPECT_EQ(g.inferred, report.bridges);
            EXPECT_EQ(analyseTopology(g).components, 1);
        } else {
            EXPECT_TRUE(report.bridges.empty()) << describe(report);
            EXPECT_EQ(analyseTopology(g).components, 2);
        }
    }
}

TEST(GapBridging, AThinLegHiddenWhereItMeetsAThickBodyJoinsTheBody) {
    // A body (tube of radius 0.2 along x) on one leg (radius 0.04) whose top 0.25 is hidden:
    // the leg's piece ends 0.45 below the body's axis, more than the gap limit of 8 node
    // spacings from it, but only 0.25 from the body's wall.
    PointList cloud = shapes::tube({{Point(-1, 0, 0), Point(1, 0, 0)}}, 0.2, 12000);
    for (const Point& p : shapes::tube({{Point(0, 0, -0.2), Point(0, 0, -1.0)}}, 0.04, 3000, 2)) {
        if (p.z() < -0.45) cloud.push_back(p);
    }
    const SkeletonResult result = computeCurveSkeleton(cloud);
    const SkeletonTopology t = analyseTopology(result.skeleton);
    EXPECT_EQ(t.components, 1) << describe(t);
    EXPECT_EQ(t.cycles, 0) << describe(t);
    EXPECT_EQ(t.tips, 3) << describe(t);
    ASSERT_EQ(result.skeleton.inferred.size(), 1u);
    const double nodeSpacing = result.quality.nodeSpacing;
    ASSERT_TRUE(result.quality.gapBridging);
    EXPECT_GT(result.quality.gapBridging->bridgeLengths[0], 8 * nodeSpacing) << "a bone longer than the limit";
}
