// Known-answer tests of the contraction (paper step 3) on sampled shapes, and on unusual
// input: a sensible result, never a crash or a hang.
#include <pcskeleton/contraction/laplacian_contraction.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace pcskeleton;

namespace {

double meanDistanceToAxis(const PointList& points, double length) {
    double sum = 0;
    for (const Point& p : points) sum += shapes::distanceToSegment(p, Point(0, 0, 0), Point(0, 0, length));
    return sum / points.size();
}

double meanDistanceToCircle(const PointList& points, double radius) {
    double sum = 0;
    for (const Point& p : points) sum += std::hypot(std::hypot(p.x(), p.y()) - radius, p.z());
    return sum / points.size();
}

double meanDistanceToOrigin(const PointList& points) {
    double sum = 0;
    for (const Point& p : points) sum += p.norm();
    return sum / points.size();
}

bool allFinite(const PointList& points) {
    return std::all_of(points.begin(), points.end(), [](const Point& p) { return p.allFinite(); });
}

}  // namespace

TEST(Contraction, CylinderContractsOntoItsAxis) {
    const PointList cloud = shapes::cylinder(4000, 0.1, 1.0, /*capped=*/true);
    const ContractionResult result = LaplacianContraction::run(cloud);
    ASSERT_EQ(result.contracted.size(), cloud.size());
    const double before = meanDistanceToAxis(cloud, 1.0);
    const double after = meanDistanceToAxis(result.contracted, 1.0);
    EXPECT_LT(after, 0.1 * before) << "mean distance to the axis " << before << " -> " << after;
    EXPECT_NE(result.stopReason, StopReason::NumericalFailure);
}

TEST(Contraction, OpenTubeWithBoundariesContractsOntoItsAxis) {
    const PointList cloud = shapes::cylinder(4000, 0.1, 1.0, /*capped=*/false);
    const ContractionResult result = LaplacianContraction::run(cloud);
    const double before = meanDistanceToAxis(cloud, 1.0);
    const double after = meanDistanceToAxis(result.contracted, 1.0);
    EXPECT_LT(after, 0.1 * before) << "mean distance to the axis " << before << " -> " << after;
}

TEST(Contraction, TorusContractsOntoItsCoreCircle) {
    const PointList cloud = shapes::torus(5000, 1.0, 0.25);
    const ContractionResult result = LaplacianContraction::run(cloud);
    const double before = meanDistanceToCircle(cloud, 1.0);
    const double after = meanDistanceToCircle(result.contracted, 1.0);
    // Measured: a fall of 83% for this fat torus (85-90% for thinner ones); what remains lies
    // well inside the thinning step's sampling balls.
    EXPECT_LT(after, 0.2 * before) << "mean distance to the core circle " << before << " -> " << after;
}

TEST(Contraction, SphereShrinksTowardsItsCentre) {
    const PointList cloud = shapes::sphere(3000, 1.0);
    const ContractionResult result = LaplacianContraction::run(cloud);
    EXPECT_LT(meanDistanceToOrigin(result.contracted), 0.5 * meanDistanceToOrigin(cloud));
}

TEST(Contraction, ConvergesInFewIterations) {
    for (const PointList& cloud : {shapes::cylinder(3000, 0.1, 1.0, true), shapes::torus(3000, 1.0, 0.25)}) {
        const ContractionResult result = LaplacianContraction::run(cloud);
        EXPECT_EQ(result.stopReason, StopReason::Converged);
        EXPECT_LE(result.iterations.size(), 8u);
    }
}

TEST(Contraction, RingsShrinkUntilConvergence) {
    LaplacianContraction contraction(shapes::sphere(3000, 1.0));
    std::vector<double> ratios;
    while (!contraction.finished()) ratios.push_back(contraction.iterate().extentRatio);
    ASSERT_GE(ratios.size(), 3u);
    // Every iteration but the last (whose small change ends the run) shrinks the rings.
    for (std::size_t i = 1; i + 1 < ratios.size(); ++i) EXPECT_LT(ratios[i], ratios[i - 1]) << "iteration " << i + 1;
    EXPECT_LT(ratios.back(), 0.1);
    EXPECT_EQ(contraction.stopReason(), StopReason::Converged);
}

TEST(Contraction, StepByStepEqualsOneCall) {
    const PointList cloud = shapes::cylinder(2000, 0.1, 1.0, true);
    LaplacianContraction stepwise(cloud);
    while (!stepwise.finished()) stepwise.iterate();
    const ContractionResult oneCall = LaplacianContraction::run(cloud);
    ASSERT_EQ(stepwise.history().size(), oneCall.iterations.size());
    const PointList a = stepwise.contractedPoints();
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_LT((a[i] - oneCall.contracted[i]).norm(), 1e-9);
}

TEST(Contraction, ResultIsScaleAndTranslationInvariant) {
    const PointList cloud = shapes::torus(3000, 1.0, 0.25);
    const ContractionResult reference = LaplacianContraction::run(cloud);
    for (double scale : {1e-3, 1e3}) {
        const Point offset(5 * scale, -3 * scale, 2 * scale);
        PointList scaled;
        for (const Point& p : cloud) scaled.push_back(p * scale + offset);
        const ContractionResult result = LaplacianContraction::run(scaled);
        ASSERT_EQ(result.iterations.size(), reference.iterations.size()) << "scale " << scale;
        double worst = 0;
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            worst = std::max(worst, ((result.contracted[i] - offset) / scale - reference.contracted[i]).norm());
        }
        // Rounding differs once coordinates are scaled; the torus' radius is 1.
        EXPECT_LT(worst, 1e-4) << "scale " << scale;
    }
}

TEST(Contraction, ASlowStartDoesNotEndTheContraction) {
    // Dense clouds (or a small W_L0) start slowly: the cotangent Laplacian's coordinates
    // shrink with the square of the spacing. The run must go on until the rings shrank.
    const PointList cloud = shapes::cylinder(3000, 0.1, 1.0, true);
    ContractionParameters p;
    p.initialContractionWeight = 0.3;
    const ContractionResult result = LaplacianContraction::run(cloud, p);
    ASSERT_GE(result.iterations.size(), 3u);
    EXPECT_GT(result.iterations[1].extentRatio, 1.0 - p.terminationThreshold) << "no slow start happened";
    EXPECT_EQ(result.stopReason, StopReason::Converged);
    EXPECT_LT(meanDistanceToAxis(result.contracted, 1.0), 0.1 * meanDistanceToAxis(cloud, 1.0));
}

TEST(Contraction, DenseCloudsContractLikeSparseOnes) {
    for (std::size_t n : {3000, 30000}) {
        const PointList cloud = shapes::cylinder(n, 0.1, 1.0, true);
        const ContractionResult result = LaplacianContraction::run(cloud);
        EXPECT_LT(meanDistanceToAxis(result.contracted, 1.0), 0.1 * meanDistanceToAxis(cloud, 1.0)) << n << " points";
    }
}

TEST(Contraction, IteratingAfterTheEndChangesNothing) {
    LaplacianContraction contraction(shapes::torus(2000, 1.0, 0.25));
    while (!contraction.finished()) contraction.iterate();
    const StopReason reason = contraction.stopReason();
    const std::size_t iterations = contraction.history().size();
    const PointList before = contraction.contractedPoints();
    contraction.iterate();
    EXPECT_EQ(contraction.stopReason(), reason);
    EXPECT_EQ(contraction.history().size(), iterations);
    EXPECT_EQ(contraction.contractedPoints(), before);
}

TEST(Contraction, IterationLimitIsHonoured) {
    ContractionParameters p;
    p.maxIterations = 1;
    const ContractionResult result = LaplacianContraction::run(shapes::torus(2000, 1.0, 0.25), p);
    EXPECT_EQ(result.iterations.size(), 1u);
    EXPECT_EQ(result.stopReason, StopReason::IterationLimit);
}

TEST(Contraction, EigenSolverMatchesCholmod) {
    const PointList cloud = shapes::torus(2000, 1.0, 0.25);
    ContractionParameters p;
    p.solver = LinearSolver::EigenSimplicial;
    const ContractionResult eigen = LaplacianContraction::run(cloud, p);
    p.solver = LinearSolver::Cholmod;
    const ContractionResult cholmod = LaplacianContraction::run(cloud, p);
    ASSERT_EQ(eigen.iterations.size(), cholmod.iterations.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_LT((eigen.contracted[i] - cholmod.contracted[i]).norm(), 1e-6);
}

TEST(BadInput, InvalidParameters) {
    ContractionParameters p;
    p.contractionScale = 0.5;
    try {
        LaplacianContraction::run(shapes::sphere(100, 1.0), p);
        ADD_FAILURE() << "s_L = 0.5 was accepted";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("s_L"), std::string::npos) << e.what();
        EXPECT_EQ(e.problem().subject, Parameter::ContractionScale);
    }
    p = {};
    p.maxIterations = 0;
    EXPECT_THROW(LaplacianContraction::run(shapes::sphere(100, 1.0), p), InvalidInput);
}

TEST(UnusualInput, ExactDuplicatesFollowTheirTwin) {
    PointList cloud = shapes::cylinder(2000, 0.1, 1.0, true);
    const std::size_t unique = cloud.size();
    for (std::size_t i = 0; i < unique; i += 3) cloud.push_back(cloud[i]);
    const ContractionResult result = LaplacianContraction::run(cloud);
    ASSERT_EQ(result.contracted.size(), cloud.size());
    ASSERT_TRUE(allFinite(result.contracted));
    for (std::size_t i = unique, j = 0; i < cloud.size(); ++i, j += 3) EXPECT_EQ(result.contracted[i], result.contracted[j]);
    double distance = 0;
    for (const Point& p : result.contracted) distance += shapes::distanceToSegment(p, Point(0, 0, 0), Point(0, 0, 1));
    EXPECT_LT(distance / cloud.size(), 0.01);
}

TEST(UnusualInput, FlatCloudContractsWithinItsPlane) {
    // A flat sheet is a surface with a boundary: it contracts from the rim, in its plane.
    PointList disc;
    for (const Point& p : shapes::sphere(3000, 1.0)) disc.emplace_back(p.x(), p.y(), 0.0);
    const ContractionResult result = LaplacianContraction::run(disc);
    ASSERT_TRUE(allFinite(result.contracted));
    for (const Point& p : result.contracted) EXPECT_NEAR(p.z(), 0.0, 1e-9);
}

TEST(UnusualInput, FarFromTheOriginAndTinyOrHugeScales) {
    const PointList cloud = shapes::cylinder(2000, 0.1, 1.0, true);
    for (double scale : {1e-6, 1e6}) {
        const Point offset(1e6, -2e6, 3e6);
        PointList moved;
        for (const Point& p : cloud) moved.push_back(p * scale + offset);
        const ContractionResult result = LaplacianContraction::run(moved);
        ASSERT_TRUE(allFinite(result.contracted));
        double distance = 0;
        for (const Point& p : result.contracted)
            distance += shapes::distanceToSegment((p - offset) / scale, Point(0, 0, 0), Point(0, 0, 1));
        EXPECT_LT(distance / cloud.size(), 0.01) << "scale " << scale;
    }
}

TEST(UnusualInput, DisconnectedComponentsContractSeparately) {
    PointList cloud = shapes::torus(3000, 1.0, 0.25, 1);
    const std::size_t first = cloud.size();
    for (const Point& p : shapes::torus(3000, 1.0, 0.25, 2)) cloud.push_back(p + Point(4, 0, 0));
    const ContractionResult result = LaplacianContraction::run(cloud);
    ASSERT_TRUE(allFinite(result.contracted));
    double before = 0, after = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const Point centre = i < first ? Point(0, 0, 0) : Point(4, 0, 0);
        auto toCircle = [&](const Point& p) {
            const Point q = p - centre;
            return std::hypot(std::hypot(q.x(), q.y()) - 1.0, q.z());
        };
        before += toCircle(cloud[i]);
        after += toCircle(result.contracted[i]);
    }
    EXPECT_LT(after, 0.2 * before);
}
