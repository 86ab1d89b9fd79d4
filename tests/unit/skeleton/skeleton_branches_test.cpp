// Branches and their measures on hand-made skeletons whose answers are known: a Y's lengths,
// orders and angle, a ring, a tapered tube's volume, the points of each branch, the root
// and the refusals.
#include <pcskeleton/skeleton/skeleton_branches.h>
#include <pcskeleton/core/errors.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>

using namespace pcskeleton;

namespace {

// Adds nodes from `from` (an existing node) to `to` in `steps` equal bones; returns the last.
int addChain(SkeletonGraph& g, int from, const Point& to, int steps, double radius = 0.1) {
    const Point start = g.nodes[std::size_t(from)];
    int previous = from;
    for (int i = 1; i <= steps; ++i) {
        g.nodes.push_back(start + (to - start) * (double(i) / steps));
        g.radii.push_back(radius);
        const int n = int(g.nodeCount()) - 1;
        g.edges.push_back({previous, n});
        previous = n;
    }
    normalizeEdges(g.edges);
    return previous;
}

SkeletonGraph singleNode(const Point& p, double radius = 0.1) {
    SkeletonGraph g;
    g.nodes.push_back(p);
    g.radii.push_back(radius);
    return g;
}

// A stem from (0, 0, 0) up to a fork at (0, 0, 1), a long arm to (0.6, 0, 1.6) and a
// short one to (-0.3, 0, 1.3): both arms leave the stem at 45 degrees.
struct Fork {
    SkeletonGraph graph = singleNode(Point::Zero());
    int fork = 0, longTip = 0, shortTip = 0;
    Fork() {
        fork = addChain(graph, 0, Point(0, 0, 1), 10);
        longTip = addChain(graph, fork, Point(0.6, 0, 1.6), 8);
        shortTip = addChain(graph, fork, Point(-0.3, 0, 1.3), 4);
    }
};

const Branch& branchEndingAt(const SkeletonBranches& b, int tip) {
    for (const Branch& branch : b.branches) {
        if (branch.nodes.back() == tip) return branch;
    }
    throw std::runtime_error("no branch ends at node " + std::to_string(tip));
}

}  // namespace

TEST(SkeletonBranches, AForkGivesThreeBranchesWithTheirLengthsOrdersAndAngles) {
    const Fork y;
    const SkeletonBranches b = measureBranches(y.graph);
    ASSERT_EQ(b.branches.size(), 3u);
    const Branch& stem = b.branches[0];
    EXPECT_EQ(stem.nodes.front(), 0) << "the lowest node is the root";
    EXPECT_EQ(stem.nodes.back(), y.fork);
    EXPECT_EQ(stem.parent, -1);
    EXPECT_EQ(stem.order, 1);
    EXPECT_NEAR(stem.length, 1.0, 1e-12);
    EXPECT_TRUE(std::isnan(stem.angleToParent));

    const Branch& longArm = branchEndingAt(b, y.longTip);
    const Branch& shortArm = branchEndingAt(b, y.shortTip);
    EXPECT_NEAR(longArm.length, 0.6 * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(shortArm.length, 0.3 * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(longArm.chord, longArm.length, 1e-12) << "a straight arm";
    EXPECT_EQ(longArm.order, 1) << "the main axis goes on into the longer continuation";
    EXPECT_EQ(shortArm.order, 2);
    EXPECT_EQ(longArm.parent, 0);
    EXPECT_NEAR(longArm.angleToParent, 45.0, 1e-9);
    EXPECT_NEAR(shortArm.angleToParent, 45.0, 1e-9);
    EXPECT_FALSE(longArm.closesLoop);
}

TEST(SkeletonBranches, TheRootAndTheUpAxisChooseWhereThePartGrowsFrom) {
    const Fork y;
    BranchOptions down;
    down.up = Point(0, 0, -1);  // the lowest node along -z is the long arm's tip
    const SkeletonBranches fromTip = measureBranches(y.graph, down);
    EXPECT_EQ(fromTip.branches[0].nodes.front(), y.longTip);
    BranchOptions atFork;
    atFork.root = y.fork;
    const SkeletonBranches fromFork = measureBranches(y.graph, atFork);
    ASSERT_EQ(fromFork.branches.size(), 3u);
    for (const Branch& branch : fromFork.branches) {
        EXPECT_EQ(branch.nodes.front(), y.fork);
        EXPECT_EQ(branch.parent, -1);
        EXPECT_EQ(branch.order, 1);
    }
}

TEST(SkeletonBranches, ARingIsOneBranchThatClosesALoop) {
    SkeletonGraph ring;
    for (int i = 0; i < 12; ++i) {
        const double a = 2 * M_PI * i / 12;
        ring.nodes.emplace_back(std::cos(a), std::sin(a), 0.1 * std::sin(a));
        ring.radii.push_back(0.1);
        ring.edges.push_back({i, (i + 1) % 12});
    }
    normalizeEdges(ring.edges);
    const SkeletonBranches b = measureBranches(ring);
    ASSERT_EQ(b.branches.size(), 1u);
    EXPECT_TRUE(b.branches[0].closesLoop);
    EXPECT_EQ(b.branches[0].nodes.front(), b.branches[0].nodes.back());
    EXPECT_EQ(b.branches[0].nodes.size(), 13u);
    double perimeter = 0;
    for (const Edge& e : ring.edges) perimeter += (ring.nodes[e[0]] - ring.nodes[e[1]]).norm();
    // The smoothing of the course leaves a bend of twelve nodes as it is, within 1%.
    EXPECT_NEAR(b.branches[0].length, perimeter, 0.01 * perimeter);
}

TEST(SkeletonBranches, BranchesAreMeasuredFromWhereTheArmsMeetNotFromTheJunctionsNode) {
    // A Y whose junction node sits 0.04 above the fork, inside its radius (0.1), as
    // contraction leaves it: the stem is measured to the fork, the arms from it.
    Fork y;
    y.graph.nodes[std::size_t(y.fork)] += Point(0, 0, 0.04);
    const SkeletonBranches b = measureBranches(y.graph);
    EXPECT_NEAR(b.branches[0].length, 1.0, 0.005);
    EXPECT_NEAR(branchEndingAt(b, y.longTip).length, 0.6 * std::sqrt(2.0), 0.005);
    EXPECT_NEAR(branchEndingAt(b, y.shortTip).length, 0.3 * std::sqrt(2.0), 0.005);
    EXPECT_NEAR(branchEndingAt(b, y.shortTip).angleToParent, 45.0, 0.5);
    // Farther than its radius past the fork, as at a fork whose arms part at a small angle:
    // the fork still lies in the stem's tube, and the branches are measured from it.
    Fork far;
    far.graph.nodes[std::size_t(far.fork)] += Point(0, 0, 0.15);
    EXPECT_NEAR(measureBranches(far.graph).branches[0].length, 1.0, 0.01);
}

TEST(SkeletonBranches, NodesBetweenTheForkAndTheJunctionsNodeAddNoLength) {
    // A stem runs on 0.2 past the fork at (0, 0, 1) to the junction's node, as where arms
    // part at a small angle: the arms leave that node sideways and then run along their lines
    // (at 45 degrees, from the fork). The stem ends at the fork, and its nodes beyond it are
    // not walked out and back.
    SkeletonGraph g = singleNode(Point::Zero());
    const int junction = addChain(g, 0, Point(0, 0, 1.2), 12);
    const int longTip = addChain(g, addChain(g, junction, Point(0.2, 0, 1.2), 1), Point(0.6, 0, 1.6), 4);
    const int shortTip = addChain(g, addChain(g, junction, Point(-0.2, 0, 1.2), 1), Point(-0.4, 0, 1.4), 2);
    const SkeletonBranches b = measureBranches(g);
    EXPECT_NEAR(b.branches[0].length, 1.0, 0.005);
    EXPECT_NEAR(b.branches[0].chord, 1.0, 0.005);
    EXPECT_NEAR(branchEndingAt(b, longTip).length, 0.6 * std::sqrt(2.0), 0.005);
    EXPECT_NEAR(branchEndingAt(b, shortTip).length, 0.4 * std::sqrt(2.0), 0.005);
}

TEST(SkeletonBranches, ALoopBackToAJunctionIsMeasuredAllRound) {
    // A lasso from the stem's top: one bone 0.5 out, then ten bones back above it, each node
    // nearer to the top than the one before. Thin (radius 0.01), so that no arm has nodes
    // near enough for a line: the fork point is the junction's node, no node lies behind it,
    // and the loop is measured all round (its corners a little rounded).
    const double radius = 0.01;
    SkeletonGraph g = singleNode(Point::Zero(), radius);
    const int top = addChain(g, 0, Point(0, 0, 1), 10, radius);
    const int out = addChain(g, top, Point(0.5, 0, 1), 1, radius);
    const int back = addChain(g, out, Point(0.05, 0, 1.1), 10, radius);
    g.edges.push_back({top, back});
    normalizeEdges(g.edges);
    const double perimeter = 0.5 + std::hypot(0.45, 0.1) + std::hypot(0.05, 0.1);
    const SkeletonBranches b = measureBranches(g);
    ASSERT_EQ(b.branches.size(), 2u);
    EXPECT_NEAR(b.branches[0].length, 1.0, 1e-9);
    EXPECT_TRUE(b.branches[1].closesLoop);
    EXPECT_NEAR(b.branches[1].length, perimeter, 0.03 * perimeter);
}

TEST(SkeletonBranches, WhereTheArmsLinesMeetOutsideEveryTubeTheJunctionsNodeIsTaken) {
    // A tuning fork (radius 0.05): two prongs rise from 0.04 either side of the stem's top,
    // leaning in, so that their lines and the stem's meet at (0, 0, 3), far outside the
    // stem's, the junction's and the prongs' tubes. The stem ends at the junction's node.
    SkeletonGraph g = singleNode(Point::Zero(), 0.05);
    const int junction = addChain(g, 0, Point(0, 0, 1), 20, 0.05);
    for (double side : {-1.0, 1.0}) {
        const int foot = addChain(g, junction, Point(0.04 * side, 0, 1), 1, 0.05);
        addChain(g, foot, Point(0.04 * side, 0, 1) + 0.5 * Point(-0.02 * side, 0, 1), 10, 0.05);
    }
    EXPECT_NEAR(measureBranches(g).branches[0].length, 1.0, 1e-9);
}

TEST(SkeletonBranches, AnArmsLineRunsOnAsLongAsTheArmIsStraightAndEndsAtABend) {
    // A Y (radius 0.1: each arm's line takes its nodes from one to five radii away, then
    // those beyond while the arm is straight) whose arms run 1.4 at 45 degrees. The nodes near the fork tilt as noise tilts them: each arm's nodes within
    // five radii lean across it by up to 0.016, the rest lie on the arm. Fitted to the near
    // nodes alone, the lines would meet off the fork; along the whole straight arm they meet
    // close to it.
    SkeletonGraph g = singleNode(Point::Zero());
    const int fork = addChain(g, 0, Point(0, 0, 1), 20);
    std::vector<int> tips;
    for (double side : {-1.0, 1.0}) {
        const int first = int(g.nodeCount());
        tips.push_back(addChain(g, fork, Point(1.0 * side, 0, 2.0), 28));
        const Point across = Point(1.0, 0, -side).normalized();
        for (int i = 2; i <= 10; ++i) g.nodes[std::size_t(first + i - 1)] += 0.004 * (i - 6) * across;
    }
    const double armLength = std::sqrt(2.0);
    SkeletonBranches b = measureBranches(g);
    EXPECT_NEAR(b.branches[0].length, 1.0, 0.004);
    for (int tip : tips) EXPECT_NEAR(branchEndingAt(b, tip).length, armLength, 0.004);

    // An arm that runs straight for 0.7 and then turns to the horizontal: its line ends at
    // the bend, and the fork stays where it is.
    Fork bent;
    const int bend = addChain(bent.graph, bent.fork, Point(0.5, 0, 1.5), 14);
    const int bentTip = addChain(bent.graph, bend, Point(1.5, 0, 1.5), 20);
    b = measureBranches(bent.graph);
    EXPECT_NEAR(b.branches[0].length, 1.0, 0.004);
    EXPECT_NEAR(branchEndingAt(b, bentTip).length, 0.5 * std::sqrt(2.0) + 1.0, 0.004);
}

TEST(SkeletonBranches, AZigzagOfNodesMeasuresTheBoneNotTheZigzag) {
    // Twenty bones along z with the nodes 0.01 to either side in turn: the zigzag is 2% longer.
    SkeletonGraph g = singleNode(Point::Zero());
    for (int i = 1; i <= 20; ++i) {
        g.nodes.emplace_back(i % 2 ? 0.01 : -0.01, 0.0, 0.05 * i);
        g.radii.push_back(0.05);
        g.edges.push_back({i - 1, i});
    }
    g.nodes.back().x() = 0;
    const SkeletonBranches b = measureBranches(g);
    ASSERT_EQ(b.branches.size(), 1u);
    EXPECT_NEAR(b.branches[0].length, 1.0, 0.002);
}

TEST(SkeletonBranches, JunctionsWhoseSpheresOverlapAreOneKnotAndTheirArmsLeaveItTogether) {
    // A stem up to (0, 0, 1) and four arms, but the junction is split in two, 0.05 apart
    // (radius 0.1): two arms leave the lower node, two the upper. Measured as one knot at the
    // fork: four arms from the stem, each as long as it is from (0, 0, 1).
    SkeletonGraph g = singleNode(Point::Zero());
    const int lower = addChain(g, 0, Point(0, 0, 0.975), 10);
    const int upper = addChain(g, lower, Point(0, 0, 1.025), 1);
    const Point ends[] = {{0.6, 0, 1.6}, {-0.6, 0, 1.6}, {0, 0.6, 1.6}, {0, -0.6, 1.6}};
    std::vector<int> tips;
    for (int arm = 0; arm < 4; ++arm) {
        const int from = arm < 2 ? lower : upper;
        // The arm's nodes run on the line from the fork (0, 0, 1) to its end.
        const int first = addChain(g, from, Point(0, 0, 1) + (ends[arm] - Point(0, 0, 1)) * 0.125, 1);
        tips.push_back(addChain(g, first, ends[arm], 7));
    }
    const SkeletonBranches b = measureBranches(g);
    ASSERT_EQ(b.branches.size(), 5u);  // the stem and four arms: the inner bone is no branch
    for (int tip : tips) {
        const Branch& arm = branchEndingAt(b, tip);
        EXPECT_EQ(arm.parent, 0);
        EXPECT_NEAR(arm.length, 0.6 * std::sqrt(2.0), 0.02);
        EXPECT_NEAR(arm.angleToParent, 45.0, 1.0);
        // At the knot the arm has the radius of its first node outside it.
        EXPECT_DOUBLE_EQ(arm.baseRadius, 0.1);
    }
    EXPECT_EQ(b.nodeBranch[std::size_t(upper)], 0);  // the knot belongs to the stem
}

TEST(SkeletonBranches, AHandleBetweenTheJunctionsOfAKnotIsALoopWithItsLength) {
    // Two junctions 0.1 apart (radius 0.1: one knot), joined by a bone and by a handle 1.1
    // long (0.5 up, 0.1 across, 0.5 down); a stem below the first, an arm to the right of
    // the second. The bone is inside the knot; the handle is a loop of the skeleton and is
    // measured as one, not taken into the knot.
    SkeletonGraph g = singleNode(Point::Zero());
    const int a = addChain(g, 0, Point(0, 0, 1), 10);
    const int b = addChain(g, a, Point(0.1, 0, 1), 1);
    addChain(g, b, Point(1, 0, 1), 9);
    const int up = addChain(g, a, Point(0, 0, 1.5), 5);
    const int across = addChain(g, up, Point(0.1, 0, 1.5), 1);
    const int down = addChain(g, across, Point(0.1, 0, 1.1), 4);
    g.edges.push_back({down, b});
    normalizeEdges(g.edges);
    const SkeletonBranches branches = measureBranches(g);
    int loops = 0;
    for (const Branch& branch : branches.branches) {
        EXPECT_GT(branch.length, 0.5);
        if (!branch.closesLoop) continue;
        ++loops;
        EXPECT_NEAR(branch.length, 1.1, 0.1);
    }
    EXPECT_EQ(loops, 1);
    EXPECT_EQ(branches.branches.size(), 3u);  // the stem, the arm and the handle
}

TEST(SkeletonBranches, ARootInsideAKnotLeavesNoFalseLoop) {
    // Two junctions 0.3 apart, joined by a chain that dips below them, each with two arms;
    // radius 1, so that they are one knot (no arm is long enough for a line: the fork points
    // are the nodes). The part's root, its lowest node, lies on the knot's inner chain: the
    // walk starts inside the knot, and neither half of that chain is a branch or a loop.
    const double radius = 1.0;
    SkeletonGraph g = singleNode(Point(0, 0, 1), radius);
    const int dip = addChain(g, 0, Point(0.1, 0, 0.9), 1, radius);
    const int b = addChain(g, addChain(g, dip, Point(0.2, 0, 0.9), 1, radius), Point(0.3, 0, 1), 1, radius);
    for (const Point& end : {Point(-0.3, 0, 1.2), Point(-0.3, 0, 1.0)}) addChain(g, 0, end, 1, radius);
    for (const Point& end : {Point(0.6, 0, 1.2), Point(0.6, 0, 1.0)}) addChain(g, b, end, 1, radius);
    const SkeletonBranches branches = measureBranches(g);
    EXPECT_EQ(branches.branches.size(), 4u);
    for (const Branch& branch : branches.branches) EXPECT_FALSE(branch.closesLoop);
}

TEST(SkeletonBranches, AKnotWhoseForkLiesBetweenItsJunctionsIsMeasuredFromTheFork) {
    // Four arms of length 1 along +-x and +-z meet at the origin, but contraction split the
    // junction into two nodes 0.099 from it, beyond their radius (0.09), joined through a
    // node at (0, 0, 0.07). The fork lies outside both junctions' balls yet inside the
    // knot's tube around its inner bone: every arm is measured from it.
    SkeletonGraph g = singleNode(Point(0, 0, -1), 0.09);
    const int lower = addChain(g, 0, Point(0, 0, -0.1), 9, 0.09);  // the -z arm, up to the knot
    g.nodes.emplace_back(0.07, 0, 0.07), g.radii.push_back(0.09);
    const int right = int(g.nodeCount()) - 1;
    g.edges.push_back({lower, right});
    const int middle = addChain(g, right, Point(0, 0, 0.07), 1, 0.09);
    const int left = addChain(g, middle, Point(-0.07, 0, 0.07), 1, 0.09);
    std::vector<int> tips;
    for (const auto& [from, start, end] : {std::tuple{right, Point(0.1, 0, 0), Point(1, 0, 0)},
                                           std::tuple{left, Point(-0.1, 0, 0), Point(-1, 0, 0)},
                                           std::tuple{left, Point(0, 0, 0.2), Point(0, 0, 1)}}) {
        const int first = addChain(g, from, start, 1, 0.09);
        tips.push_back(addChain(g, first, end, int(std::lround((end - start).norm() / 0.1)), 0.09));
    }
    const SkeletonBranches b = measureBranches(g);
    ASSERT_EQ(b.branches.size(), 4u);  // the inner bone is no branch
    EXPECT_NEAR(b.branches[0].length, 1.0, 0.001);  // the root's, from the lowest node up
    for (int tip : tips) EXPECT_NEAR(branchEndingAt(b, tip).length, 1.0, 0.001) << "the arm ending at node " << tip;
}

TEST(SkeletonBranches, ATaperedTubeHasTheVolumeAndRadiiOfItsCone) {
    // Radius 0.3 at the base to 0.1 at the tip over a length of 2: a truncated cone.
    SkeletonGraph g = singleNode(Point::Zero(), 0.3);
    for (int i = 1; i <= 20; ++i) addChain(g, i - 1, Point(0, 0, 0.1 * i), 1, 0.3 - 0.01 * i);
    const Branch branch = measureBranches(g).branches.at(0);
    EXPECT_NEAR(branch.baseRadius, 0.3, 1e-12);
    EXPECT_NEAR(branch.tipRadius, 0.1, 1e-12);
    EXPECT_NEAR(branch.meanRadius, 0.2, 1e-12);
    EXPECT_NEAR(branch.volume, M_PI * 2.0 / 3.0 * (0.09 + 0.03 + 0.01), 1e-12);
}

TEST(SkeletonBranches, EachPointGetsItsNodesBranchAndItsPlaceAlongIt) {
    Fork y;
    // One point per node; the fork's point belongs to the stem, which reaches it.
    for (std::size_t n = 0; n < y.graph.nodeCount(); ++n) y.graph.pointNode.push_back(int(n));
    y.graph.pointNode.push_back(-1);  // a point without a node (an outlier)
    const SkeletonBranches b = measureBranches(y.graph);
    EXPECT_EQ(b.pointBranch[std::size_t(y.fork)], 0);
    EXPECT_NEAR(b.pointPosition[std::size_t(y.fork)], 1.0, 1e-12);
    EXPECT_EQ(b.pointBranch[0], 0);
    EXPECT_NEAR(b.pointPosition[0], 0.0, 1e-12);
    const int longArm = b.nodeBranch[std::size_t(y.longTip)];
    EXPECT_EQ(b.pointBranch[std::size_t(y.longTip)], longArm);
    EXPECT_NEAR(b.pointPosition[std::size_t(y.longTip)], 1.0, 1e-12);
    EXPECT_NEAR(b.pointPosition[std::size_t(y.longTip - 4)], 0.5, 1e-12) << "halfway along the long arm";
    EXPECT_EQ(b.pointBranch.back(), -1);
    EXPECT_TRUE(std::isnan(b.pointPosition.back()));
    EXPECT_EQ(b.branches[0].points, 11);
    EXPECT_EQ(b.branches[std::size_t(longArm)].points, 8);
}

TEST(SkeletonBranches, GivenThePointsAJunctionsPointsGoToTheArmTheyLieAlong) {
    // The Y's junction node holds points of its three arms, 0.06 from the fork along each.
    Fork y;
    const Point fork(0, 0, 1);
    const Point along[] = {Point(0, 0, -1), Point(1, 0, 1).normalized(), Point(-1, 0, 1).normalized()};
    const int tipOf[] = {0, y.longTip, y.shortTip};
    PointList points;
    for (const Point& direction : along) {
        for (double side : {-0.01, 0.01}) {
            points.push_back(fork + 0.06 * direction + Point(0, side, 0));
            y.graph.pointNode.push_back(y.fork);
        }
    }
    const SkeletonBranches byNode = measureBranches(y.graph);
    for (int branch : byNode.pointBranch) EXPECT_EQ(branch, 0);  // all the stem's, which reaches the junction
    const SkeletonBranches byPoint = measureBranches(y.graph, points);
    for (std::size_t arm = 0; arm < 3; ++arm) {
        const int expected = arm == 0 ? 0 : int(&branchEndingAt(byPoint, tipOf[arm]) - byPoint.branches.data());
        for (std::size_t i = 2 * arm; i < 2 * arm + 2; ++i) {
            EXPECT_EQ(byPoint.pointBranch[i], expected) << "point " << i;
            // At its place along the branch: near the stem's top, near the arms' base.
            EXPECT_NEAR(byPoint.pointPosition[i], arm == 0 ? 1.0 - 0.06 / 1.0 : 0.06 / byPoint.branches[std::size_t(expected)].length, 0.01);
        }
    }
    EXPECT_EQ(byPoint.branches[0].points, 2);
    EXPECT_THROW(measureBranches(y.graph, PointList(points.begin(), points.end() - 1)), CallerError);
}

TEST(SkeletonBranches, PartsGrowFromTheirOwnRootsAndLoneNodesHaveNoBranch) {
    SkeletonGraph g = singleNode(Point(0, 0, 0));
    addChain(g, 0, Point(0, 0, 1), 5);
    g.nodes.emplace_back(5, 0, 2);  // a node on its own
    g.radii.push_back(0.1);
    g.nodes.emplace_back(3, 0, 1);  // a second part, built top-down
    g.radii.push_back(0.1);
    addChain(g, int(g.nodeCount()) - 1, Point(3, 0, -1), 4);
    const SkeletonBranches b = measureBranches(g);
    ASSERT_EQ(b.branches.size(), 2u);
    EXPECT_EQ(b.branches[1].nodes.front(), int(g.nodeCount()) - 1) << "its lowest node";
    EXPECT_EQ(b.nodeBranch[6], -1);
}

TEST(SkeletonBranches, OnRandomGraphsEachCycleIsOneLoopBranchAndEveryBoneIsMeasuredOnce) {
    // Graphs of 2 to 40 nodes with random bones, at scales from 1e-6 to 100 against radii
    // from 0.01 to 10 (tiny scales make every pair of junctions one knot), some with nodes
    // on top of each other: whatever the knots and roots, the loop branches are as many as
    // the skeleton's independent cycles, no bone is in two branches, and every length is
    // finite.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> gaussian;
    for (int trial = 0; trial < 500; ++trial) {
        SkeletonGraph g;
        const int n = 2 + int(unit(random) * 38);
        const double scale = std::pow(10.0, -6.0 + 8.0 * unit(random)), radius = std::pow(10.0, -2.0 + 3.0 * unit(random));
        for (int i = 0; i < n; ++i) {
            g.nodes.push_back(scale * Point(gaussian(random), gaussian(random), gaussian(random)));
            g.radii.push_back(radius * (0.5 + unit(random)));
        }
        if (unit(random) < 0.2) std::fill(g.nodes.begin(), g.nodes.begin() + n / 2, g.nodes.front());
        const int bones = int(unit(random) * 2 * n);
        for (int e = 0; e < bones; ++e) g.edges.push_back({int(unit(random) * n), int(unit(random) * n)});
        normalizeEdges(g.edges);
        const SkeletonBranches b = measureBranches(g);
        int loops = 0;
        std::size_t branchBones = 0;
        for (const Branch& branch : b.branches) {
            loops += branch.closesLoop;
            branchBones += branch.nodes.size() - 1;
            EXPECT_TRUE(std::isfinite(branch.length) && branch.length >= 0.0) << "trial " << trial;
        }
        EXPECT_EQ(loops, analyseTopology(g).cycles) << "trial " << trial;
        EXPECT_LE(branchBones, g.edges.size()) << "trial " << trial;
    }
}

TEST(SkeletonBranches, AZeroUpAxisOrARootThatIsNoNodeIsRefused) {
    const Fork y;
    BranchOptions flat;
    flat.up = Point::Zero();
    EXPECT_THROW(measureBranches(y.graph, flat), InvalidInput);
    for (int bad : {-2, int(y.graph.nodeCount())}) {
        BranchOptions wrong;
        wrong.root = bad;
        try {
            measureBranches(y.graph, wrong);
            ADD_FAILURE() << "root " << bad << " accepted";
        } catch (const InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("is not a node of the skeleton"), std::string::npos) << e.what();
        }
    }
}
