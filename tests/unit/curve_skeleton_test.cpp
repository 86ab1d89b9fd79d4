// Known-answer tests of the whole pipeline (contraction, thinning, embedding, tip
// extension) on tubes along known curves.
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/contraction/contraction_memory.h>
#include <pcskeleton/internal/median.h>
#include <pcskeleton/io/point_cloud_io.h>
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace pcskeleton;
using shapes::Polyline;

namespace {

constexpr double kPi = 3.14159265358979323846;

SkeletonTopology topologyOf(const PointList& cloud, const SkeletonParameters& parameters = {}) {
    const SkeletonResult result = computeCurveSkeleton(cloud, parameters);
    return analyseTopology(result.skeleton);
}

double diagonalOf(const PointList& points) {
    Point low = points.front(), high = points.front();
    for (const Point& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
    return (high - low).norm();
}

Polyline yShape(double armLength) {
    Polyline arms;
    for (int i = 0; i < 3; ++i) {
        const double angle = 2 * kPi * i / 3 + kPi / 2;
        arms.push_back({Point::Zero(), armLength * Point(std::cos(angle), std::sin(angle), 0)});
    }
    return arms;
}

// Two rings touching at the origin: a figure eight, genus 2.
Polyline figureEight(double ringRadius) {
    Polyline curve = shapes::circle(Point(-ringRadius, 0, 0), ringRadius);
    const Polyline right = shapes::circle(Point(ringRadius, 0, 0), ringRadius);
    // Rotate the right ring by half a side so that neither ring has a corner at the origin twice.
    curve.insert(curve.end(), right.begin(), right.end());
    return curve;
}

// A permutation of the input gives the same skeleton: the same nodes and bones, and each
// point the same node. Sums over the points in the input's order (radii, the finishing
// steps' fits) may round differently in the last digits.
void expectTheSameSkeletonInAnyOrder(const PointList& cloud, const SkeletonParameters& parameters) {
    std::vector<std::size_t> order(cloud.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(7));
    PointList shuffled;
    for (std::size_t i : order) shuffled.push_back(cloud[i]);
    const SkeletonResult a = computeCurveSkeleton(cloud, parameters), b = computeCurveSkeleton(shuffled, parameters);
    ASSERT_EQ(a.skeleton.nodeCount(), b.skeleton.nodeCount());
    EXPECT_EQ(a.skeleton.edges, b.skeleton.edges);
    const double tolerance = 1e-9 * diagonalOf(cloud);
    for (std::size_t n = 0; n < a.skeleton.nodeCount(); ++n) {
        EXPECT_LT((a.skeleton.nodes[n] - b.skeleton.nodes[n]).norm(), tolerance) << "node " << n;
        EXPECT_NEAR(a.skeleton.radii[n], b.skeleton.radii[n], tolerance) << "node " << n;
    }
    for (std::size_t k = 0; k < order.size(); ++k) {
        ASSERT_EQ(b.skeleton.pointNode[k], a.skeleton.pointNode[order[k]]) << "input point " << order[k];
    }
}

}  // namespace

TEST(CurveSkeleton, TorusHasExactlyOneCycle) {
    const SkeletonTopology t = topologyOf(shapes::torus(6000, 1.0, 0.25));
    EXPECT_EQ(t.cycles, 1) << describe(t);
    EXPECT_EQ(t.components, 1) << describe(t);
    EXPECT_EQ(t.tips, 0) << describe(t);
}

TEST(CurveSkeleton, GenusTwoShapeHasTwoCycles) {
    const SkeletonTopology t = topologyOf(shapes::tube(figureEight(1.0), 0.22, 10000));
    EXPECT_EQ(t.cycles, 2) << describe(t);
    EXPECT_EQ(t.components, 1) << describe(t);
}

TEST(CurveSkeleton, SphereHasNoCycle) {
    const SkeletonTopology t = topologyOf(shapes::sphere(4000, 1.0));
    EXPECT_EQ(t.cycles, 0) << describe(t);
    EXPECT_EQ(t.components, 1) << describe(t);
}

// A flat square of 500 points, the sheets step off: the paper's k for so few is 8, and fans
// from 8 neighbours contract the square into a web of false loops (docs/benchmarks.md,
// "Sparse clouds"). The default k is 20 there.
TEST(CurveSkeleton, ASparseFlatSquareContractsWithoutLoops) {
    const shapes::Triangles square = shapes::sheet([](double u, double v) { return Point(u, v, 0); }, 1, 1);
    SkeletonParameters defaultK, papersK;
    defaultK.graph.collapseSheets = papersK.graph.collapseSheets = false;
    papersK.contraction.papersNeighbourRule = true;
    int loopsWithThePapersK = 0;
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        const PointList cloud = shapes::sample(square, 500, seed);
        EXPECT_EQ(topologyOf(cloud, defaultK).cycles, 0) << "seed " << seed;
        loopsWithThePapersK += topologyOf(cloud, papersK).cycles;
    }
    EXPECT_GT(loopsWithThePapersK, 0) << "the case tells the two rules apart";
}

TEST(CurveSkeleton, YShapedTubeHasThreeTipsAndOneJunction) {
    const SkeletonTopology t = topologyOf(shapes::tube(yShape(1.0), 0.12, 8000));
    EXPECT_EQ(t.tips, 3) << describe(t);
    EXPECT_EQ(t.junctions, 1) << describe(t);
    EXPECT_EQ(t.cycles, 0) << describe(t);
}

TEST(CurveSkeleton, StraightTubeGivesAPathAlongItsAxis) {
    const PointList cloud = shapes::cylinder(5000, 0.1, 1.0, /*capped=*/true);
    const SkeletonResult result = computeCurveSkeleton(cloud);
    const SkeletonTopology t = analyseTopology(result.skeleton);
    EXPECT_EQ(t.components, 1) << describe(t);
    EXPECT_EQ(t.cycles, 0) << describe(t);
    EXPECT_EQ(t.tips, 2) << describe(t);
    EXPECT_EQ(t.junctions, 0) << describe(t);
    const double tolerance = 0.02 * diagonalOf(cloud);
    for (const Point& node : result.skeleton.nodes) {
        // On the axis line, and inside the capsule lengthwise (tip nodes sit in the caps).
        EXPECT_LT(std::hypot(node.x(), node.y()), tolerance) << node.transpose();
        EXPECT_GT(node.z(), -0.1);
        EXPECT_LT(node.z(), 1.1);
    }
    // The path covers most of the axis, not one clump.
    double lowest = 1, highest = 0;
    for (const Point& node : result.skeleton.nodes) lowest = std::min(lowest, node.z()), highest = std::max(highest, node.z());
    EXPECT_GT(highest - lowest, 0.7);
}

TEST(CurveSkeleton, NonUniformTubeKeepsItsTopology) {
    // Half of the points in 10% of the length.
    const Polyline axis = {{Point(0, 0, 0), Point(0, 0, 1)}};
    PointList cloud = shapes::tube({{Point(0, 0, 0), Point(0, 0, 0.1)}}, 0.1, 2500, 7);
    const PointList rest = shapes::tube({{Point(0, 0, 0.1), Point(0, 0, 1)}}, 0.1, 2500, 8);
    for (const Point& p : rest) {
        if (p.z() > 0.1) cloud.push_back(p);  // the dense part's cap stays, the sparse one's inside is dropped
    }
    PointList kept;
    for (const Point& p : cloud) {
        if (shapes::distanceToCurve(p, axis) >= 0.1 * (1 - 1e-6)) kept.push_back(p);
    }
    const SkeletonTopology t = topologyOf(kept);
    EXPECT_EQ(t.components, 1) << describe(t);
    EXPECT_EQ(t.cycles, 0) << describe(t);
    EXPECT_EQ(t.tips, 2) << describe(t);
    EXPECT_EQ(t.junctions, 0) << describe(t);
}

TEST(CurveSkeleton, CorrespondenceAndRadiiDescribeTheTube) {
    const PointList cloud = shapes::cylinder(5000, 0.1, 1.0, /*capped=*/false);
    SkeletonParameters paperSteps;
    paperSteps.graph.extendTips = false;  // its end nodes own no points (TipExtension tests them)
    const SkeletonResult result = computeCurveSkeleton(cloud, paperSteps);
    const SkeletonGraph& s = result.skeleton;
    ASSERT_EQ(s.pointNode.size(), cloud.size());
    ASSERT_EQ(s.radii.size(), s.nodes.size());
    std::vector<int> members(s.nodes.size(), 0);
    for (int node : s.pointNode) {
        ASSERT_GE(node, 0);
        ASSERT_LT(node, int(s.nodes.size()));
        ++members[node];
    }
    for (std::size_t n = 0; n < s.nodes.size(); ++n) {
        EXPECT_GT(members[n], 0) << "node " << n << " stands for no point";
        // Away from the open ends the radius is the tube's.
        if (s.nodes[n].z() > 0.2 && s.nodes[n].z() < 0.8) EXPECT_NEAR(s.radii[n], 0.1, 0.01);
    }
    // Every point belongs to a node near it along the axis. Contraction pulls an open end's
    // node in by about the tube's radius (tip extension, off here, makes up for it): the
    // rim's points may be that and a node spacing (0.02) from their node.
    const std::vector<int> degree = nodeDegrees(s.nodeCount(), s.edges);
    for (std::size_t i = 0; i < cloud.size(); i += 50) {
        const int node = s.pointNode[i];
        const double allowed = degree[std::size_t(node)] == 1 ? 0.1 + 0.02 : 0.1;
        EXPECT_LT(std::abs(cloud[i].z() - s.nodes[node].z()), allowed) << "point " << i;
    }
}

// Noise of a third of the tube's radius: the bones' radii are still the tube's, measured
// across the bone with the noise taken out (finishing/bone_radii.h); the mean distance of
// each node's points, the embedding's radius, is well above it.
double medianMiddleRadius(const SkeletonGraph& s, const std::vector<double>& radii) {
    std::vector<double> middle;
    for (std::size_t n = 0; n < s.nodeCount(); ++n) {
        if (s.nodes[n].z() > 0.2 && s.nodes[n].z() < 0.8) middle.push_back(radii[n]);
    }
    return middle.empty() ? 0.0 : median(middle);
}

TEST(CurveSkeleton, ANoisyTubesRadiiAreTheTubesNotTheNoises) {
    const PointList clean = shapes::cylinder(5000, 0.1, 1.0, /*capped=*/false);
    const double diagonal = std::sqrt(1.0 + 0.2 * 0.2 * 2);
    const PointList cloud = shapes::withNoise(clean, 0.03 / diagonal, 5);
    const SkeletonResult result = computeCurveSkeleton(cloud);
    const SkeletonGraph& s = result.skeleton;
    // Within 5% of the tube's radius; the noise's deviation is 30% of it.
    EXPECT_NEAR(medianMiddleRadius(s, s.radii), 0.1, 0.005);
    EXPECT_GT(medianMiddleRadius(s, meanDistanceToNodes(cloud, s.pointNode, s.nodes)), 0.105);
}

// An outlier far from the torus becomes a node owning one point: its radius (a distance
// to itself, 0) is taken from its neighbours, so every skeleton can be edited as it comes.
TEST(CurveSkeleton, EveryNodeHasAPositiveRadiusEvenWithOutliers) {
    PointList cloud = shapes::torus(3000, 1.0, 0.3);
    cloud.emplace_back(0, 0, 1.5);
    cloud.emplace_back(2.5, 0, 0.8);
    const SkeletonResult result = computeCurveSkeleton(cloud);
    EXPECT_EQ(invariantViolation(result.skeleton), "");
    for (double r : result.skeleton.radii) EXPECT_GT(r, 0.0);
}

TEST(CurveSkeleton, TwoStagesEqualOneCall) {
    const PointList cloud = shapes::torus(3000, 1.0, 0.3);
    const SkeletonResult oneCall = computeCurveSkeleton(cloud);
    const SkeletonGraph fromContracted =
        skeletonFromContractedPoints(cloud, oneCall.contraction.contracted, ContractionParameters{}, SkeletonGraphParameters()).skeleton;
    EXPECT_EQ(fromContracted.edges, oneCall.skeleton.edges);
    EXPECT_EQ(fromContracted.pointNode, oneCall.skeleton.pointNode);
}

// Above the subsample's size too: the contracted points of every input point, thinned again
// with the run's parameters, give the run's skeleton (thinning the subsample, not all points).
TEST(CurveSkeleton, ContractedPointsThinnedThroughTheRunsSubsampleGiveItsSkeleton) {
    const PointList cloud = shapes::tube(yShape(1.0), 0.12, 4000);
    SkeletonParameters parameters;
    parameters.resolution.maxContractedPoints = 2500;
    const SkeletonResult run = computeCurveSkeleton(cloud, parameters);
    ASSERT_EQ(run.contraction.contracted.size(), cloud.size());
    const SkeletonResult again = skeletonFromContractedPoints(cloud, run.contraction.contracted, parameters);
    EXPECT_EQ(again.skeleton.nodes, run.skeleton.nodes);
    EXPECT_EQ(again.skeleton.edges, run.skeleton.edges);
    EXPECT_EQ(again.skeleton.pointNode, run.skeleton.pointNode);
    EXPECT_EQ(again.skeleton.radii, run.skeleton.radii);
    EXPECT_EQ(again.quality.inputPoints, cloud.size());
    EXPECT_LE(again.quality.points, parameters.resolution.maxContractedPoints);

    // A damaged point is refused also where it is not in the subsample (and so not thinned).
    const ContractionInput work(cloud, parameters.resolution, parameters.contraction.outliers);
    const std::vector<int>& kept = work.subsample().kept;
    std::size_t notKept = 0;
    while (std::binary_search(kept.begin(), kept.end(), int(notKept))) ++notKept;
    PointList damaged = run.contraction.contracted;
    damaged[notKept].x() = std::nan("");
    EXPECT_THROW(skeletonFromContractedPoints(cloud, damaged, parameters), InvalidInput);
}

// Trying thinning's parameters on one contraction gives what a whole run with them gives,
// through the subsample too, and leaves the pipeline's own parameters as they were.
TEST(CurveSkeleton, OneContractionThinnedWithOtherParametersEqualsAWholeRunWithThem) {
    const PointList cloud = shapes::tube(yShape(1.0), 0.12, 4000);
    SkeletonParameters parameters;
    parameters.resolution.maxContractedPoints = 2500;
    SkeletonPipeline pipeline(cloud, parameters);
    pipeline.contraction().iterateToEnd({});
    const SkeletonResult first = pipeline.skeleton();

    SkeletonParameters coarse = parameters;
    coarse.graph.nodeSpacing = 0.06;
    coarse.graph.refine = false;
    const SkeletonResult tried = pipeline.skeleton(coarse.graph);
    const SkeletonResult wholeRun = computeCurveSkeleton(cloud, coarse);
    EXPECT_EQ(tried.skeleton.nodes, wholeRun.skeleton.nodes);
    EXPECT_EQ(tried.skeleton.edges, wholeRun.skeleton.edges);
    EXPECT_EQ(tried.skeleton.pointNode, wholeRun.skeleton.pointNode);
    EXPECT_LT(tried.skeleton.nodeCount(), first.skeleton.nodeCount());

    const SkeletonResult again = pipeline.skeleton();
    EXPECT_EQ(again.skeleton.nodes, first.skeleton.nodes);
    EXPECT_EQ(again.skeleton.edges, first.skeleton.edges);

    SkeletonGraphParameters unusable = parameters.graph;
    unusable.gapLimit = -1;
    EXPECT_THROW(pipeline.skeleton(unusable), InvalidInput);
}

TEST(CurveSkeleton, ScaleDoesNotChangeTheGraph) {
    const PointList cloud = shapes::tube(yShape(1.0), 0.12, 4000);
    PointList scaled;
    for (const Point& p : cloud) scaled.push_back(p * 1e4 + Point(5e5, 0, 0));
    const SkeletonResult a = computeCurveSkeleton(cloud), b = computeCurveSkeleton(scaled);
    EXPECT_EQ(a.skeleton.edges, b.skeleton.edges);
    ASSERT_EQ(a.skeleton.radii.size(), b.skeleton.radii.size());
    for (std::size_t n = 0; n < a.skeleton.radii.size(); ++n) {
        EXPECT_NEAR(b.skeleton.radii[n], 1e4 * a.skeleton.radii[n], 1e-6 * b.skeleton.radii[n]);
    }
}

// Down to the smallest and up to the largest scale whose squared distances a double
// holds, the same skeleton (beyond, point_cloud_input_test: refused with the reason).
TEST(CurveSkeleton, ExtremeScalesKeepTheTorusCycle) {
    const PointList torus = shapes::torus(3000, 1.0, 0.25);
    const SkeletonResult reference = computeCurveSkeleton(torus);
    for (double scale : {1e99, 1e-99}) {
        PointList scaled;
        for (const Point& p : torus) scaled.push_back(p * scale);
        const SkeletonResult result = computeCurveSkeleton(scaled);
        EXPECT_EQ(analyseTopology(result.skeleton).cycles, 1) << scale;
        EXPECT_EQ(result.skeleton.edges, reference.skeleton.edges) << scale;
    }
}

TEST(CurveSkeleton, SamplingRadiusMustBeAFraction) {
    SkeletonParameters p;
    p.graph.nodeSpacing = 0;
    EXPECT_THROW(computeCurveSkeleton(shapes::sphere(500, 1.0), p), InvalidInput);
    p.graph.nodeSpacing = 1.5;
    EXPECT_THROW(computeCurveSkeleton(shapes::sphere(500, 1.0), p), InvalidInput);
}

// A scan of bench_robustness's suite as `--write` saves it, from tests/data/scans.
PointList savedScan(const std::string& file) { return readPointCloud(std::string(PCSKELETON_SCANS_DIR) + "/" + file); }

// A saved scan of bench_robustness's libcgal-demo knot (one loop) whose false loops
// refinement cuts as `bridges` stray bridges and `loopsOverData` loops over data: one loop,
// no tip, one part; without refinement, `unrefinedCycles`. `parameters`: the rest.
void expectTheKnotsOneLoop(const std::string& file, int bridges, int loopsOverData, int unrefinedCycles,
                           const SkeletonParameters& parameters = {}) {
    const PointList scan = savedScan(file);
    const SkeletonQuality q = computeCurveSkeleton(scan, parameters).quality;
    ASSERT_TRUE(q.refinement);
    EXPECT_EQ(q.refinement->bridgesCut, bridges) << describe(*q.refinement);
    EXPECT_EQ(q.refinement->filledLoopsCut, loopsOverData) << describe(*q.refinement);
    EXPECT_TRUE(q.topology.cycles == 1 && q.topology.tips == 0 && q.topology.components == 1) << describe(q.topology);
    SkeletonParameters unrefined = parameters;
    unrefined.graph.refine = false;
    EXPECT_EQ(computeCurveSkeleton(scan, unrefined).quality.topology.cycles, unrefinedCycles);
}

// With 0.5% noise: at a crossing, three points of the two strands' facing walls were pulled
// into the gap between them and made a node that joined the strands, a second loop.
TEST(CurveSkeleton, AKnotWithLittleNoiseKeepsItsOneLoop) { expectTheKnotsOneLoop("knot_noise05_6000.ply", 1, 0, 2); }

// With half its points in 10% of the surface: at the crossings the strands' 1-rings reach
// across the gaps between them. With the facing walls kept apart no false loop forms. With
// them in the 1-rings, thinning joins the strands by bones across the gaps (three false
// loops): one is opened as a narrow loop; that leaves part of a strand on no loop, across
// the two others (partAcrossLoop), which are opened as loops over data at those bones.
TEST(CurveSkeleton, AKnotSampledUnevenlyKeepsItsOneLoop) {
    expectTheKnotsOneLoop("knot_half_in_10_6000.ply", 0, 0, 1);
    SkeletonParameters facingWallsTogether;
    facingWallsTogether.contraction.separateFacingWalls = false;
    expectTheKnotsOneLoop("knot_half_in_10_6000.ply", 0, 2, 4, facingWallsTogether);
}

// bench_robustness's figure eight (two holes) with 5% outliers: outliers near the junctions
// thinned into loops whose own points cover their inside. Refinement opens both: the first,
// then the second, which shared a bone with it and is measured again once it is opened.
// Without the hole test they stay, and without refinement the report names them.
TEST(CurveSkeleton, AFigureEightWithOutliersKeepsItsTwoHolesOnly) {
    const PointList scan = savedScan("genus2_outliers5_6300.ply");
    const SkeletonQuality q = computeCurveSkeleton(scan).quality;
    EXPECT_EQ(q.topology.cycles, 2) << describe(q.topology);
    ASSERT_TRUE(q.refinement);
    EXPECT_EQ(q.refinement->filledLoopsCut, 2) << describe(*q.refinement);
    EXPECT_NE(describe(*q.refinement).find(", 2 loops over data,"), std::string::npos) << describe(*q.refinement);

    SkeletonParameters noHoleTest;
    noHoleTest.graph.refinementLimits.minHole = 0;
    EXPECT_EQ(computeCurveSkeleton(scan, noHoleTest).quality.topology.cycles, 4);

    SkeletonParameters unrefined;
    unrefined.graph.refine = false;
    const SkeletonQuality raw = computeCurveSkeleton(scan, unrefined).quality;
    EXPECT_FALSE(raw.filledLoops.empty());
    const auto warnings = raw.warnings();
    EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(),
                            [](const QualityWarning& w) { return w.kind == QualityWarning::Kind::FilledLoops; }))
        << describe(raw);
    EXPECT_TRUE(q.filledLoops.empty()) << "refinement opened it: no warning";
}

// bench_robustness's figure with its arms close to its body (0.06 from it, the legs 0.06
// apart), clean: a point's 30 nearest reach across both gaps. With those neighbours in
// the 1-rings the body's pull drags the arms into it, and the skeleton joins each arm's ends
// to the middle of the body; with the facing walls kept apart each arm has its own bone
// from the shoulder down: the five ends.
TEST(CurveSkeleton, ArmsBesideTheBodyKeepTheirOwnBones) {
    const PointList scan = savedScan("figure_clean_4984.ply");
    const SkeletonResult r = computeCurveSkeleton(scan);
    EXPECT_TRUE(r.quality.topology.tips == 5 && r.quality.topology.cycles == 0 && r.quality.topology.components == 1)
        << describe(r.quality.topology);
    ASSERT_TRUE(r.quality.contraction);
    EXPECT_GT(r.quality.contraction->facingNeighboursLeftOut, 0);

    SkeletonParameters together;
    together.contraction.separateFacingWalls = false;
    const SkeletonQuality q = computeCurveSkeleton(scan, together).quality;
    EXPECT_GT(q.topology.tips, 5) << describe(q.topology);
    EXPECT_EQ(q.contraction->facingNeighboursLeftOut, -1);
    EXPECT_NE(describe(q).find("Facing walls: off."), std::string::npos);
}

// bench_robustness's figure with its arms close to its body, seen once from the side, and
// its hand (a fist) scanned from one view: an arm in front of the body, and the curled
// fingers in front of the palm, hide what is behind them, and contraction rings each shadow
// with a loop whose own points leave its inside empty, like a hole's. A limb lies across
// it (partAcrossLoop): refinement opens it. Without the loops-over-data test the figure's
// stays; the fist's is then cut as a stray bridge, once refinement has absorbed a corner
// limb beside it.
TEST(CurveSkeleton, OneViewShadowsBehindLimbsAreNotHoles) {
    for (const char* file : {"figure_one_view_side_4189.ply", "hand_one_view_4936.ply"}) {
        SCOPED_TRACE(file);
        const PointList scan = savedScan(file);
        const SkeletonQuality q = computeCurveSkeleton(scan).quality;
        EXPECT_EQ(q.topology.cycles, 0) << describe(q.topology);
        EXPECT_EQ(q.topology.components, 1) << describe(q.topology);
        ASSERT_TRUE(q.refinement);
        EXPECT_GE(q.refinement->filledLoopsCut, 1) << describe(*q.refinement);
    }
    // Without the hole test the loop stays, unless its bone is cut as one over a gap in the
    // data, which is a test of its own.
    SkeletonParameters noHoleTest;
    noHoleTest.graph.refinementLimits.minHole = 0;
    noHoleTest.graph.refinementLimits.gapStretch = 0;
    EXPECT_EQ(computeCurveSkeleton(savedScan("figure_one_view_side_4189.ply"), noHoleTest).quality.topology.cycles, 1);
}

// bench_robustness's figure with its arms close to its body, seen from above: the left
// arm's lowest points are drawn to the hip 0.07 away, and thinning joins the arm's end to
// the body with one bone across space where the scan has no points. Refinement cuts it as
// a bone over a gap in the data (the gap stretch 0 keeps it): the figure's five ends, no loop.
TEST(CurveSkeleton, AnArmBesideTheBodySeenFromAboveIsNotJoinedToIt) {
    const PointList scan = savedScan("figure_one_view_above_2823.ply");
    const SkeletonQuality q = computeCurveSkeleton(scan).quality;
    EXPECT_EQ(q.topology.cycles, 0) << describe(q.topology);
    EXPECT_EQ(q.topology.components, 1) << describe(q.topology);
    EXPECT_EQ(q.topology.tips, 5) << describe(q.topology);

    SkeletonParameters noGapCuts;
    noGapCuts.graph.refinementLimits.gapStretch = 0;
    EXPECT_EQ(computeCurveSkeleton(scan, noGapCuts).quality.topology.cycles, 1);
}

// bench_robustness's plant scanned from one view: a leaf in front of the stem hides a
// stretch of it, and each of the stem's two pieces turns into a leaf where it ends, so
// neither has a tip pointing at the other. The stem's corners look ahead.
TEST(CurveSkeleton, AStemHiddenWhereItTurnsIntoALeafIsBridgedFromTheCorner) {
    const PointList scan = savedScan("plant_one_view_7962.ply");
    const SkeletonResult r = computeCurveSkeleton(scan);
    EXPECT_EQ(r.quality.topology.components, 1) << describe(r.quality.topology);
    EXPECT_EQ(r.quality.topology.cycles, 0) << describe(r.quality.topology);
    EXPECT_EQ(r.quality.topology.tips, 8) << describe(r.quality.topology);  // six leaves, the stem's two ends
    ASSERT_TRUE(r.quality.gapBridging);
    const std::vector<Edge>& bridges = r.quality.gapBridging->bridges;
    const auto acrossTheHiddenStretch = [&](const Edge& e) {
        const Point& a = r.skeleton.nodes[std::size_t(e[0])];
        const Point& b = r.skeleton.nodes[std::size_t(e[1])];
        return std::min(a.z(), b.z()) < 0.85 && std::max(a.z(), b.z()) > 0.95;
    };
    EXPECT_EQ(std::count_if(bridges.begin(), bridges.end(), acrossTheHiddenStretch), 1)
        << describe(*r.quality.gapBridging);
}

// bench_robustness's two close tubes (surfaces 0.12 apart) with 1% noise: noise put a
// point in the gap, contraction left it there, and thinning made it a node joining the
// tubes side by side.
TEST(CurveSkeleton, TwoCloseTubesWithNoiseStayTwoParts) {
    const PointList scan = savedScan("two_tubes_noise1_6000.ply");
    const SkeletonQuality q = computeCurveSkeleton(scan).quality;
    ASSERT_TRUE(q.refinement);
    EXPECT_EQ(q.refinement->bridgesCut, 1) << describe(*q.refinement);
    EXPECT_TRUE(q.topology.components == 2 && q.topology.tips == 4 && q.topology.cycles == 0) << describe(q.topology);
}

// bench_robustness's three rings (genus 3) with 1% noise, as `--write` saves it: noise
// joins two rings across their narrow gap, a loop the refinement opens.
TEST(CurveSkeleton, NoisyThreeRingsKeepTheirThreeLoopsOnly) {
    const PointList scan = savedScan("three_rings_noise1_6000.ply");
    const SkeletonResult r = computeCurveSkeleton(scan);
    EXPECT_EQ(r.quality.topology.cycles, 3) << describe(r.quality.topology);
    EXPECT_EQ(r.quality.topology.components, 1) << describe(r.quality.topology);
    ASSERT_TRUE(r.quality.refinement);
    EXPECT_EQ(r.quality.refinement->cyclesCut, 1) << describe(*r.quality.refinement);

    // Left whole as a narrow loop and by the hole test, the loop goes at the bone across the
    // gap between the rings.
    SkeletonParameters noNarrowLoop;
    noNarrowLoop.graph.refinementLimits.minOpening = 0;
    noNarrowLoop.graph.refinementLimits.minHole = 0;
    const SkeletonQuality gap = computeCurveSkeleton(scan, noNarrowLoop).quality;
    EXPECT_EQ(gap.topology.cycles, 3) << describe(gap.topology);
    ASSERT_TRUE(gap.refinement);
    EXPECT_EQ(gap.refinement->bridgesCut, 1) << describe(*gap.refinement);
    SkeletonParameters keepEveryLoop = noNarrowLoop;
    keepEveryLoop.graph.refinementLimits.gapStretch = 0;
    EXPECT_EQ(computeCurveSkeleton(scan, keepEveryLoop).quality.topology.cycles, 4);
    // The hole test alone opens it too: its own points cover its inside.
    SkeletonParameters holeTestOnly = keepEveryLoop;
    holeTestOnly.graph.refinementLimits.minHole = RefinementLimits{}.minHole;
    const SkeletonQuality filled = computeCurveSkeleton(scan, holeTestOnly).quality;
    EXPECT_EQ(filled.topology.cycles, 3) << describe(filled.topology);
    ASSERT_TRUE(filled.refinement);
    EXPECT_EQ(filled.refinement->filledLoopsCut, 1) << describe(*filled.refinement);

    // Without refinement the loop stays, and the report says what it probably is.
    SkeletonParameters unrefined;
    unrefined.graph.refine = false;
    const SkeletonQuality q = computeCurveSkeleton(scan, unrefined).quality;
    EXPECT_EQ(q.topology.cycles, 4) << describe(q.topology);
    EXPECT_EQ(q.contactLoops.size(), 1u);
    const auto warnings = q.warnings();
    const auto contact = std::find_if(warnings.begin(), warnings.end(), [](const QualityWarning& w) {
        return w.kind == QualityWarning::Kind::ContactLoops;
    });
    ASSERT_NE(contact, warnings.end()) << describe(q);
    EXPECT_NE(contact->problem.description.find("1 loop is narrower than the tube"), std::string::npos)
        << contact->problem.description;
    EXPECT_TRUE(r.quality.contactLoops.empty()) << "refinement opened it: no warning";
}

TEST(CurveSkeleton, NarrowLoopLimitsMustBeInRange) {
    const PointList cloud = shapes::sphere(500, 1.0);
    SkeletonParameters p;
    p.graph.refinementLimits.minOpening = -1;
    EXPECT_THROW(computeCurveSkeleton(cloud, p), InvalidInput);
    p.graph.refinementLimits.minOpening = std::nan("");
    EXPECT_THROW(computeCurveSkeleton(cloud, p), InvalidInput);
    p = SkeletonParameters();
    p.graph.refinementLimits.minClearance = 1.5;
    EXPECT_THROW(computeCurveSkeleton(cloud, p), InvalidInput);
    p = SkeletonParameters();
    p.graph.refinementLimits.gapStretch = 0.5;
    EXPECT_THROW(computeCurveSkeleton(cloud, p), InvalidInput);
    p.graph.refinementLimits.gapStretch = std::numeric_limits<double>::infinity();
    EXPECT_THROW(computeCurveSkeleton(cloud, p), InvalidInput);
    p = SkeletonParameters();
    p.graph.refinementLimits.minHole = -0.5;
    EXPECT_THROW(computeCurveSkeleton(cloud, p), InvalidInput);
    p.graph.refinementLimits.minHole = std::nan("");
    EXPECT_THROW(computeCurveSkeleton(cloud, p), InvalidInput);
}

TEST(CurveSkeleton, ContractedPointsMustMatchTheInput) {
    const PointList cloud = shapes::sphere(500, 1.0);
    const ContractionParameters contraction;
    const SkeletonGraphParameters thinning;
    EXPECT_THROW(skeletonFromContractedPoints(cloud, PointList(10, Point::Zero()), contraction, thinning), InvalidInput);
    EXPECT_THROW(skeletonFromContractedPoints(cloud, PointList(10, Point::Zero()), SkeletonParameters{}), InvalidInput);
    PointList withNaN = cloud;
    withNaN[3].x() = std::nan("");
    EXPECT_THROW(skeletonFromContractedPoints(cloud, withNaN, contraction, thinning), InvalidInput);
    EXPECT_THROW(skeletonFromContractedPoints(cloud, withNaN, SkeletonParameters{}), InvalidInput);
}

// Multi-resolution: 200K points contracted through a subsample of 20K (the default), with
// every input point given its node and the radii measured on all of them.
TEST(MultiResolution, LargeTorusHasOneCycleAndEveryPointItsNode) {
    const PointList cloud = shapes::torus(200000, 1.0, 0.25, 11);
    const SkeletonResult result = computeCurveSkeleton(cloud);
    const SkeletonTopology t = analyseTopology(result.skeleton);
    EXPECT_EQ(t.cycles, 1) << describe(t);
    EXPECT_EQ(t.components, 1) << describe(t);
    EXPECT_EQ(t.tips, 0) << describe(t);
    EXPECT_EQ(result.quality.inputPoints, cloud.size());
    EXPECT_LE(result.quality.points, ResolutionParameters{}.maxContractedPoints);
    ASSERT_EQ(result.skeleton.pointNode.size(), cloud.size());
    for (int node : result.skeleton.pointNode) ASSERT_GE(node, 0);
    ASSERT_EQ(result.contraction.contracted.size(), cloud.size());
    for (std::size_t n = 0; n < result.skeleton.nodeCount(); ++n) {
        EXPECT_NEAR(result.skeleton.radii[n], 0.25, 0.025) << "node " << n;
    }
    EXPECT_NE(describeFindings(result.quality).find("multi-resolution: "), std::string::npos);
}

// The same through the multi-resolution pipeline, whose radii come from every point.
TEST(MultiResolution, ANoisyTorusesRadiiAreItsTubes) {
    const PointList cloud = shapes::withNoise(shapes::torus(100000, 1.0, 0.25, 11), 0.08 / std::sqrt(2.5 * 2.5 * 2 + 0.25), 6);
    const SkeletonResult result = computeCurveSkeleton(cloud);
    ASSERT_EQ(analyseTopology(result.skeleton).cycles, 1);
    EXPECT_NEAR(median(result.skeleton.radii), 0.25, 0.0075);
}

TEST(MultiResolution, LargeYHasThreeTips) {
    const PointList cloud = shapes::tube(yShape(1.0), 0.12, 200000, 12);
    const SkeletonResult result = computeCurveSkeleton(cloud);
    const SkeletonTopology t = analyseTopology(result.skeleton);
    EXPECT_EQ(t.tips, 3) << describe(t);
    EXPECT_EQ(t.junctions, 1) << describe(t);
    EXPECT_EQ(t.cycles, 0) << describe(t);
    for (int node : result.skeleton.pointNode) ASSERT_GE(node, 0);
    // Radii along the arms, away from the junction and the rounded ends.
    for (std::size_t n = 0; n < result.skeleton.nodeCount(); ++n) {
        const double fromCentre = result.skeleton.nodes[n].norm();
        if (fromCentre > 0.3 && fromCentre < 0.8) EXPECT_NEAR(result.skeleton.radii[n], 0.12, 0.012) << "node " << n;
    }
}

// Outliers are found on the whole cloud before the grid, which would keep each isolated
// point as surely as a patch of surface: they get no node.
TEST(MultiResolution, OutliersOfTheWholeCloudGetNoNode) {
    PointList cloud = shapes::torus(60000, 1.0, 0.25, 13);
    const std::size_t surface = cloud.size();
    for (int i = 0; i < 300; ++i) {
        const double a = 0.37 * i, b = 0.91 * i;
        cloud.emplace_back(1.6 * std::cos(a), 1.6 * std::sin(a), 0.9 * std::sin(b));
    }
    SkeletonParameters parameters;
    parameters.resolution.maxContractedPoints = 8000;
    const SkeletonResult result = computeCurveSkeleton(cloud, parameters);
    EXPECT_EQ(analyseTopology(result.skeleton).cycles, 1) << describe(analyseTopology(result.skeleton));
    std::size_t withoutNode = 0;
    for (std::size_t i = surface; i < cloud.size(); ++i) withoutNode += result.skeleton.pointNode[i] < 0;
    EXPECT_GE(withoutNode, 290u);
    EXPECT_GE(result.quality.inputOutliers, 290u);
}

TEST(MultiResolution, FullResolutionContractsEveryPoint) {
    const PointList cloud = shapes::torus(12000, 1.0, 0.25, 14);
    SkeletonParameters parameters;
    parameters.resolution.maxContractedPoints = 5000;
    EXPECT_LE(computeCurveSkeleton(cloud, parameters).quality.points, 5000u);
    parameters.resolution.maxContractedPoints = 0;
    const SkeletonResult full = computeCurveSkeleton(cloud, parameters);
    EXPECT_EQ(full.quality.points, cloud.size());
    EXPECT_EQ(describeFindings(full.quality).find("multi-resolution"), std::string::npos);
    EXPECT_EQ(SkeletonParameters::paper().resolution.maxContractedPoints, 0u) << "the paper contracts every point";
}

TEST(MultiResolution, SameSkeletonRunAfterRun) {
    const PointList cloud = shapes::tube(yShape(1.0), 0.12, 40000, 15);
    SkeletonParameters parameters;
    parameters.resolution.maxContractedPoints = 6000;
    const SkeletonResult a = computeCurveSkeleton(cloud, parameters), b = computeCurveSkeleton(cloud, parameters);
    EXPECT_EQ(a.skeleton.nodes, b.skeleton.nodes);
    EXPECT_EQ(a.skeleton.edges, b.skeleton.edges);
    EXPECT_EQ(a.skeleton.pointNode, b.skeleton.pointNode);
}

// The paper's tobacco plant: its broad leaf went through the sheets step or not depending
// on which point the file listed first (12 nodes in the file's order, 20 to 45 in shuffled
// orders).
TEST(CurveSkeleton, TheOrderOfTheInputDoesNotChangeTheSkeleton) {
    expectTheSameSkeletonInAnyOrder(readPointCloud(PCSKELETON_SCANS_DIR "/tobacco_v8098.ply"), {});
}

// The same through the subsample, whose cube size is searched on a sample of this cloud.
TEST(MultiResolution, TheOrderOfTheInputDoesNotChangeTheSkeleton) {
    SkeletonParameters parameters;
    parameters.resolution.maxContractedPoints = 300;
    expectTheSameSkeletonInAnyOrder(shapes::tube(yShape(1.0), 0.12, 40000, 15), parameters);
}

// A cloud too big for the memory given is refused before any work, with the size it needs.
TEST(MultiResolution, CloudTooBigForMemoryIsRefusedWithTheSizeItNeeds) {
    const PointList cloud = shapes::sphere(30000, 1.0);
    SkeletonParameters parameters;
    parameters.resolution.maxContractedPoints = 0;
    parameters.resolution.memoryLimit = 20e6;  // 20 MB: full resolution needs about 80
    try {
        computeCurveSkeleton(cloud, parameters);
        FAIL() << "no refusal";
    } catch (const InvalidInput& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find("30000 points"), std::string::npos) << text;
        EXPECT_NE(text.find("0.081 GB"), std::string::npos) << text;
        EXPECT_NE(text.find("number of contracted points"), std::string::npos) << text;
    }
    parameters.resolution.maxContractedPoints = 5000;  // about 16 MB
    EXPECT_NO_THROW(computeCurveSkeleton(cloud, parameters));
    EXPECT_GT(estimatedPeakBytes(10000000, 20000), 1e9);
    EXPECT_LT(estimatedPeakBytes(10000000, 20000), 2e9);
}

// Just over the threshold, and under it once the outliers are set aside: no grid, and the
// report says why every other point was contracted.
TEST(MultiResolution, JustOverTheThresholdWithOutliersContractsEveryOtherPoint) {
    PointList cloud = shapes::torus(2995, 1.0, 0.25, 16);
    for (int i = 0; i < 10; ++i) cloud.emplace_back(3.0 + 0.5 * i, 2.0, 1.5);
    SkeletonParameters parameters;
    parameters.resolution.maxContractedPoints = 3000;
    const SkeletonResult result = computeCurveSkeleton(cloud, parameters);
    EXPECT_EQ(analyseTopology(result.skeleton).cycles, 1);
    EXPECT_EQ(result.quality.points, 2995u);
    const std::string report = describeFindings(result.quality);
    EXPECT_NE(report.find("multi-resolution: 2995 contracted (all but the outliers: few enough)"), std::string::npos)
        << report;
}

// Long work shows progress: the subsample's steps first, never going backwards, to 100.
// Scanners and merged scans repeat points exactly: 16 copies of each point (more than the
// outlier test's neighbours) are one point each, not a cloud of isolated clumps.
TEST(MultiResolution, ExactDuplicatesAreOnePointEach) {
    const PointList torus = shapes::torus(1000, 1.0, 0.25);
    PointList copies;
    for (int copy = 0; copy < 16; ++copy) copies.insert(copies.end(), torus.begin(), torus.end());
    SkeletonParameters parameters;
    ASSERT_GT(copies.size(), parameters.resolution.maxContractedPoints);
    const SkeletonResult result = computeCurveSkeleton(copies, parameters);
    EXPECT_EQ(analyseTopology(result.skeleton).cycles, 1);
    EXPECT_EQ(result.quality.inputOutliers, 0u);
    ASSERT_EQ(result.skeleton.pointNode.size(), copies.size());
    for (std::size_t i = 0; i < copies.size(); ++i) {
        EXPECT_EQ(result.skeleton.pointNode[i], result.skeleton.pointNode[i % torus.size()]) << i;
    }
}

TEST(MultiResolution, ProgressRisesThroughTheSubsample) {
    const PointList cloud = shapes::torus(12000, 1.0, 0.25, 17);
    SkeletonParameters parameters;
    parameters.resolution.maxContractedPoints = 4000;
    std::vector<int> percents;
    std::vector<std::string> steps;
    computeCurveSkeleton(cloud, parameters, [&](int percent, const char* what) {
        percents.push_back(percent);
        steps.emplace_back(what);
    });
    ASSERT_FALSE(percents.empty());
    EXPECT_TRUE(std::is_sorted(percents.begin(), percents.end()));
    EXPECT_EQ(percents.back(), 100);
    EXPECT_EQ(steps.front(), "Multi-resolution: outliers of the whole cloud");
}
