// The quality report, the optional refinement and tip extension: on hand-made graphs whose
// flaws are known, and through the whole pipeline on shapes whose skeleton is known.
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/sampled_shapes.h>
#include <pcskeleton/scan_simulation.h>
#include <pcskeleton/skeleton_refinement.h>
#include <pcskeleton/skeleton_structure.h>
#include <pcskeleton/tip_extension.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace pcskeleton;

namespace {

constexpr double kSpacing = 0.1;

// Nodes 0..10 along the x axis, kSpacing apart, radius 0.2.
SkeletonGraph straightChain() {
    SkeletonGraph g;
    for (int i = 0; i <= 10; ++i) {
        g.nodes.emplace_back(kSpacing * i, 0, 0);
        g.radii.push_back(0.2);
        if (i > 0) g.edges.push_back({i - 1, i});
    }
    return g;
}

int addNode(SkeletonGraph& g, const Point& p, int connectTo) {
    g.nodes.push_back(p);
    g.radii.push_back(0.2);
    const int n = int(g.nodeCount()) - 1;
    g.edges.push_back({connectTo, n});
    normalizeEdges(g.edges);
    return n;
}

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

    const RefinementReport report = refineSkeleton(g, kSpacing);
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
}

TEST(SkeletonRefinement, LeavesACleanSkeletonAlone) {
    SkeletonGraph ring = shapes::curveSkeleton(shapes::circle(Point::Zero(), 1.0, 24), 0.3);
    const SkeletonGraph before = ring;
    EXPECT_FALSE(refineSkeleton(ring, kSpacing).changedAnything());
    EXPECT_EQ(ring.edges, before.edges);
}

// A capped tube along z from 0 to 1 (radius 0.1): the shape ends at z = -0.1 and 1.1.
struct TipEnds {
    double low, high;
};

TipEnds tipEnds(const SkeletonGraph& g) {
    const std::vector<int> degree = nodeDegrees(g.nodeCount(), g.edges);
    TipEnds ends{1e9, -1e9};
    for (std::size_t n = 0; n < g.nodeCount(); ++n) {
        if (degree[n] != 1) continue;
        ends.low = std::min(ends.low, g.nodes[n].z());
        ends.high = std::max(ends.high, g.nodes[n].z());
    }
    return ends;
}

TEST(TipExtension, ReachesTheEndsOfACappedTube) {
    const PointList cloud = shapes::cylinder(6000, 0.1, 1.0, /*capped=*/true);
    SkeletonParameters paper;
    paper.thinning.extendTips = false;
    const SkeletonResult short_ = computeCurveSkeleton(cloud, paper);
    const SkeletonResult extended = computeCurveSkeleton(cloud);
    ASSERT_EQ(analyseTopology(short_.skeleton).tips, 2);
    ASSERT_EQ(analyseTopology(extended.skeleton).tips, 2);
    EXPECT_EQ(extended.quality.tipExtension.extendedTips, 2);
    EXPECT_EQ(invariantViolation(extended.skeleton), "");

    const TipEnds before = tipEnds(short_.skeleton), after = tipEnds(extended.skeleton);
    // Contraction leaves the ends inside; extension brings them to the caps' apexes.
    EXPECT_GT(before.low, -0.1 + 0.03);
    EXPECT_LT(before.high, 1.1 - 0.03);
    EXPECT_NEAR(after.low, -0.1, 0.01);
    EXPECT_NEAR(after.high, 1.1, 0.01);
    // The new end nodes own no points; the old tips keep theirs.
    EXPECT_EQ(extended.skeleton.pointNode, short_.skeleton.pointNode);
}

TEST(TipExtension, LeavesLoopsAndSpursAlone) {
    SkeletonGraph ring = shapes::curveSkeleton(shapes::circle(Point::Zero(), 1.0, 24), 0.3);
    EXPECT_EQ(extendTips(ring, {}, kSpacing).extendedTips, 0);
    SkeletonGraph g = straightChain();
    const int spur = addNode(g, Point(0.5, 0.1, 0), 5);
    PointList points{Point(0.5, 0.5, 0)};  // far along the spur
    g.pointNode = {spur};
    const std::size_t nodes = g.nodeCount();
    extendTips(g, points, kSpacing);
    EXPECT_EQ(g.nodeCount(), nodes) << "a spur (or an end without points) is not extended";
}

TEST(QualityReport, ATorusGivesOneCycleAndNoWarning) {
    const SkeletonResult result = computeCurveSkeleton(shapes::torus(6000, 1.0, 0.3));
    const SkeletonQuality& q = result.quality;
    EXPECT_EQ(q.topology.cycles, 1);
    EXPECT_EQ(q.topology.tips, 0);
    EXPECT_EQ(q.stopReason, StopReason::Converged);
    EXPECT_GT(q.iterations, 0);
    EXPECT_EQ(q.inputParts, 1);
    EXPECT_EQ(q.uncontractedPoints, 0u);
    EXPECT_TRUE(q.warnings().empty()) << describe(q);
    const std::string text = describe(q);
    EXPECT_NE(text.find("1 cycle"), std::string::npos) << text;
    EXPECT_NE(text.find("converged"), std::string::npos) << text;
    EXPECT_NE(text.find("No warnings."), std::string::npos) << text;
}

TEST(QualityReport, OutliersAreReported) {
    const PointList cloud = shapes::withOutliers(shapes::torus(6000, 1.0, 0.3), 0.05, 3);
    const SkeletonResult result = computeCurveSkeleton(cloud);
    const std::string text = describe(result.quality);
    EXPECT_GT(result.quality.uncontractedPoints + result.quality.pointsOfIsolatedNodes, 0u) << text;
    EXPECT_FALSE(result.quality.warnings().empty()) << text;
    EXPECT_NE(text.find("Remove outliers"), std::string::npos) << text;
}

TEST(QualityReport, APartThatCollapsesToAPointIsReported) {
    // A torus and, far from it, a small ball: the ball contracts to a point, no bone.
    PointList cloud = shapes::torus(6000, 1.0, 0.3);
    for (Point p : shapes::sphere(400, 0.15, 5)) cloud.push_back(p + Point(3.0, 0, 0));
    const SkeletonResult result = computeCurveSkeleton(cloud);
    EXPECT_EQ(result.quality.inputParts, 2) << describe(result.quality);
    EXPECT_EQ(result.quality.partsWithoutBone, 1) << describe(result.quality);
    EXPECT_EQ(result.quality.pointsWithoutBone, 400u) << describe(result.quality);
}

TEST(QualityReport, IterationLimitIsAWarning) {
    SkeletonParameters oneIteration;
    oneIteration.contraction.maxIterations = 1;
    const SkeletonResult result = computeCurveSkeleton(shapes::torus(3000, 1.0, 0.3), oneIteration);
    EXPECT_EQ(result.quality.stopReason, StopReason::IterationLimit);
    const std::vector<std::string> warnings = result.quality.warnings();
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings.front().find("maximum iterations"), std::string::npos) << warnings.front();
}

TEST(QualityReport, RefinementIsReportedWhenOn) {
    SkeletonParameters refine;
    refine.thinning.refine = true;
    const SkeletonResult result = computeCurveSkeleton(shapes::torus(4000, 1.0, 0.3), refine);
    EXPECT_TRUE(result.quality.refined);
    EXPECT_EQ(result.quality.topology.cycles, 1) << "refinement must keep a real loop";
    EXPECT_NE(describe(result.quality).find("Refinement: removed"), std::string::npos);
}

TEST(ScanSimulation, PerturbationsDoWhatTheySay) {
    const PointList sphere = shapes::sphere(20000, 1.0, 2);
    EXPECT_EQ(shapes::withOutliers(sphere, 0.05).size(), 21000u);
    // One view of a sphere sees most of its front half (grazing parts are lost, as with
    // real scanners) and nothing of the back (pixels of about three sample spacings).
    const PointList front = shapes::visibleFrom(sphere, Point(0, 0, 1), 0.08);
    EXPECT_GT(double(front.size()) / sphere.size(), 0.35);
    EXPECT_LT(double(front.size()) / sphere.size(), 0.5);
    for (const Point& p : front) ASSERT_LT(p.z(), 0.3) << "a point on the far side is visible";
    // Half of the points in 10% of the surface.
    const PointList uneven = shapes::unevenlyDense(sphere, 4000, 0.1, 3);
    ASSERT_EQ(uneven.size(), 4000u);
    const double diagonal = boundingBox(sphere).diagonal().norm();
    const PointList noisy = shapes::withNoise(sphere, 0.01, 4);
    double squared = 0;
    for (std::size_t i = 0; i < sphere.size(); ++i) squared += (noisy[i] - sphere[i]).squaredNorm();
    EXPECT_NEAR(std::sqrt(squared / (3.0 * sphere.size())), 0.01 * diagonal, 0.001 * diagonal);
}

}  // namespace
