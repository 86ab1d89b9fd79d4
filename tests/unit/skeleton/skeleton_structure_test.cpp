// Limbs, spurs and spurious loops on hand-made graphs whose flaws are known.
#include <pcskeleton/skeleton/skeleton_structure.h>
#include <pcskeleton/curve_skeleton.h>
#include "support/hand_made_graphs.h"
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pcskeleton;
using namespace pcskeleton::graphs;

TEST(SkeletonStructure, AShortLimbInsideTheBodyIsASpurALongOneIsNot) {
    SkeletonGraph g = straightChain();
    const int spurTip = addNode(g, Point(0.5, 0.1, 0), 5);  // 0.1 long, the body is 0.2 thick
    int limbTip = 7;
    for (int step = 1; step <= 5; ++step) limbTip = addNode(g, Point(0.7, 0.1 * step, 0), limbTip);
    int spurs = 0, limbs = 0;
    for (const Limb& limb : tipLimbs(g)) {
        if (limb.path.front() == spurTip) {
            EXPECT_TRUE(isSpur(g, limb, kSpacing));
            ++spurs;
        }
        if (limb.path.front() == limbTip) {
            EXPECT_FALSE(isSpur(g, limb, kSpacing));
            ++limbs;
        }
        if (limb.path.front() == 0 || limb.path.front() == 10) EXPECT_FALSE(isSpur(g, limb, kSpacing));
    }
    EXPECT_EQ(spurs, 1);
    EXPECT_EQ(limbs, 1);
}

namespace {

// Points on the wall of the chain's 0.2 tube (x from 0 to 1), each given its nearest node.
PointList wallPoints(SkeletonGraph& g) {
    PointList points;
    for (int i = 0; i <= 100; ++i) {
        for (int a = 0; a < 24; ++a) {
            const double angle = 2.0 * M_PI * a / 24.0;
            points.emplace_back(0.01 * i, 0.2 * std::cos(angle), 0.2 * std::sin(angle));
        }
    }
    g.pointNode.assign(points.size(), -1);
    for (std::size_t p = 0; p < points.size(); ++p) g.pointNode[p] = int(std::lround(points[p].x() / kSpacing));
    return points;
}

// Gives each point whose nearest node is one of `nodes` (among those and the chain's) to it.
void giveNearestPoints(SkeletonGraph& g, const PointList& points, const std::vector<int>& nodes) {
    for (std::size_t p = 0; p < points.size(); ++p) {
        double best = (points[p] - g.nodes[g.pointNode[p]]).norm();
        for (int n : nodes) {
            if ((points[p] - g.nodes[n]).norm() < best) best = (points[p] - g.nodes[n]).norm(), g.pointNode[p] = n;
        }
    }
}

}  // namespace

TEST(SkeletonStructure, ALimbWhosePointsTheBoneAccountsForIsRedundant) {
    // A limb sprouting sideways from node 5 towards the wall, 0.3 long (longer than the
    // 0.2 radius, so not a short spur), owning wall points only: noise made it.
    SkeletonGraph g = straightChain();
    PointList points = wallPoints(g);
    const int a = addNode(g, Point(0.5, 0.1, 0.1), 5);
    const int tip = addNode(g, Point(0.5, 0.15, 0.15), a);
    giveNearestPoints(g, points, {a, tip});
    // A real leg: from node 8 out of the tube to 0.7 away, with its own thin tube of points.
    int legTip = 8;
    std::vector<int> leg;
    for (int step = 1; step <= 7; ++step) leg.push_back(legTip = addNode(g, Point(0.8, 0, -0.1 * step), legTip));
    for (int i = 20; i <= 70; ++i) {
        for (int c = 0; c < 8; ++c) {
            const double angle = 2.0 * M_PI * c / 8.0;
            points.emplace_back(0.8 + 0.04 * std::cos(angle), 0.04 * std::sin(angle), -0.01 * i);
            g.pointNode.push_back(8);
        }
    }
    giveNearestPoints(g, points, leg);
    for (int n : leg) g.radii[n] = 0.04;

    const std::vector<std::vector<int>> nodePoints = pointsOfNodes(g);
    int checked = 0;
    for (const Limb& limb : tipLimbs(g)) {
        if (limb.path.front() == tip) {
            EXPECT_FALSE(isSpur(g, limb, kSpacing)) << "longer than the radius";
            EXPECT_TRUE(isRedundantLimb(g, limb, points, nodePoints, kSpacing));
            EXPECT_FALSE(isRedundantLimb(g, limb, {}, nodePoints, kSpacing)) << "no points, no judgement";
            ++checked;
        }
        if (limb.path.front() == legTip) {
            EXPECT_FALSE(isRedundantLimb(g, limb, points, nodePoints, kSpacing)) << "its points lie outside the body";
            ++checked;
        }
    }
    EXPECT_EQ(checked, 2);
}

TEST(SkeletonStructure, ALoopWithoutAHoleIsSpuriousARingIsNot) {
    SkeletonGraph g = straightChain();
    // A square loop of side 0.05 hanging on node 5: the 0.2 tube around it fills it.
    const int a = addNode(g, Point(0.5, 0.05, 0), 5);
    const int b = addNode(g, Point(0.55, 0.05, 0), a);
    const int c = addNode(g, Point(0.55, 0.0, 0.02), b);
    g.edges.push_back({5, c});
    normalizeEdges(g.edges);
    const auto cycles = shortCycleBasis(g);
    ASSERT_EQ(cycles.size(), 1u);
    EXPECT_EQ(cycles[0].size(), 4u);
    EXPECT_TRUE(isSpuriousCycle(g, cycles[0], kSpacing));

    const SkeletonGraph ring = shapes::curveSkeleton(shapes::circle(Point::Zero(), 1.0, 24), 0.3);
    const auto ringCycles = shortCycleBasis(ring);
    ASSERT_EQ(ringCycles.size(), 1u);
    EXPECT_EQ(ringCycles[0].size(), 24u);
    EXPECT_FALSE(isSpuriousCycle(ring, ringCycles[0], kSpacing));
}

// A bracket: two plates at right angles, two bolt holes in each. Around a hole in a sheet
// every bone lies on the surface, so the narrow-loop test for parts that touch must not take
// the hole's loop for a contact: one loop per hole.
TEST(SkeletonStructure, EveryBoltHoleOfABracketKeepsItsLoop) {
    const auto holes = [](double u, double v) {
        return std::hypot((u - 0.25) * 1.2, (v - 0.55) * 0.8) > 0.12 && std::hypot((u - 0.75) * 1.2, (v - 0.55) * 0.8) > 0.12;
    };
    shapes::Triangles bracket = shapes::sheet([](double u, double v) { return Point(1.2 * u, 0.8 * v, 0); }, 60, 40, holes);
    const shapes::Triangles upright =
        shapes::sheet([](double u, double v) { return Point(1.2 * u, 0, 0.8 * v); }, 60, 40, holes);
    bracket.insert(bracket.end(), upright.begin(), upright.end());
    const SkeletonResult result = computeCurveSkeleton(shapes::sample(bracket, 6000, 11));
    EXPECT_EQ(analyseTopology(result.skeleton).cycles, 4) << describe(result.quality);
    EXPECT_EQ(analyseTopology(result.skeleton).components, 1);
}

// A ring's loop goes round its hole. The same loop holding the points of a dome over it
// (a one-view scan of a rounded part contracts to a ring along its rim) goes round data.
TEST(SkeletonStructure, ALoopRoundItsPointsIsFilledALoopRoundAHoleIsNot) {
    const shapes::Polyline circle = shapes::circle(Point::Zero(), 1.0, 24);
    SkeletonGraph ring = shapes::curveSkeleton(circle, 0.2);
    const PointList tube = shapes::tube(circle, 0.2, 4000);
    giveEachPointItsNearestNode(ring, tube);
    const auto cycles = shortCycleBasis(ring);
    ASSERT_EQ(cycles.size(), 1u);
    // The tube's inner wall is 0.8 from the centre; the 24-gon's corners cut the circle by 1%.
    EXPECT_NEAR(emptyDiscRadius(ring, cycles[0], tube, pointsOfNodes(ring), 0.01), 0.8, 0.03);

    SkeletonGraph dome = ring;
    PointList cap;
    for (int i = 0; i < 60; ++i) {
        for (int j = 0; j < 60; ++j) {
            const double x = -1.0 + (i + 0.5) / 30.0, y = -1.0 + (j + 0.5) / 30.0;
            if (x * x + y * y <= 1.0) cap.emplace_back(x, y, 0.5 * (1.0 - x * x - y * y));
        }
    }
    giveEachPointItsNearestNode(dome, cap);
    // The cap's points stand on a grid 1/30 apart: the widest empty disc is the grid's cell.
    EXPECT_LT(emptyDiscRadius(dome, cycles[0], cap, pointsOfNodes(dome), 0.01), 0.05);

    constexpr double nodeSpacing = 0.26;  // the 24-gon's bones
    EXPECT_TRUE(filledLoops(ring, tube, nodeSpacing, RefinementLimits{}).empty());
    const std::vector<LoopToOpen> filled = filledLoops(dome, cap, nodeSpacing, RefinementLimits{});
    ASSERT_EQ(filled.size(), 1u);
    EXPECT_EQ(filled[0].cycle.size(), 24u);
    RefinementLimits none;
    none.minHole = 0;
    EXPECT_TRUE(filledLoops(dome, cap, nodeSpacing, none).empty());
}
