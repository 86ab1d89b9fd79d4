// The quality report through the whole pipeline, on shapes whose skeleton is known.
#include <pcskeleton/curve_skeleton.h>
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

using namespace pcskeleton;

TEST(QualityReport, ATorusGivesOneCycleAndNoWarning) {
    const SkeletonResult result = computeCurveSkeleton(shapes::torus(6000, 1.0, 0.3));
    const SkeletonQuality& q = result.quality;
    EXPECT_EQ(q.topology.cycles, 1);
    EXPECT_EQ(q.topology.tips, 0);
    ASSERT_TRUE(q.contraction);
    EXPECT_EQ(q.contraction->stopReason, StopReason::Converged);
    EXPECT_GT(q.contraction->iterations, 0);
    EXPECT_EQ(q.inputParts, 1);
    EXPECT_EQ(q.uncontractedPoints, 0u);
    EXPECT_TRUE(q.warnings().empty()) << describe(q);
    const std::string text = describe(q);
    EXPECT_NE(text.find("1 cycle"), std::string::npos) << text;
    EXPECT_NE(text.find("converged"), std::string::npos) << text;
    EXPECT_NE(text.find("No warnings."), std::string::npos) << text;
}

TEST(QualityReport, OutliersAreSetAsideAndReported) {
    const PointList torus = shapes::torus(6000, 1.0, 0.3);
    const PointList cloud = shapes::withOutliers(torus, 0.05, 3);
    const SkeletonResult result = computeCurveSkeleton(cloud);
    EXPECT_EQ(result.quality.topology.cycles, 1) << describe(result.quality);
    EXPECT_EQ(result.quality.topology.components, 1) << describe(result.quality);
    EXPECT_GT(result.quality.outliers, 100u) << "most of the 300 outliers are far from the torus";
    std::size_t onTorus = 0, marked = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const int node = result.skeleton.pointNode[i];
        if (i < torus.size()) onTorus += node < 0;
        else marked += node < 0;
    }
    EXPECT_EQ(onTorus, 0u) << "a point of the torus was taken for an outlier";
    EXPECT_EQ(marked, result.quality.outliers) << "outliers have no node";
    EXPECT_NE(describe(result.quality).find(std::to_string(result.quality.outliers) + " outliers set aside"),
              std::string::npos) << describe(result.quality);
}

TEST(QualityReport, OutliersAreReportedByThePapersPipeline) {
    const PointList cloud = shapes::withOutliers(shapes::torus(6000, 1.0, 0.3), 0.05, 3);
    const SkeletonResult result = computeCurveSkeleton(cloud, SkeletonParameters::paper());
    const std::string text = describe(result.quality);
    EXPECT_GT(result.quality.uncontractedPoints + result.quality.pointsOfIsolatedNodes, 0u) << text;
    EXPECT_FALSE(result.quality.warnings().empty()) << text;
    EXPECT_NE(text.find("Remove outliers"), std::string::npos) << text;
    const std::vector<QualityWarning> warnings = result.quality.warnings();
    EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [](const QualityWarning& w) {
        return w.problem.suggests(Remedy::take(Step::RemoveOutliers));
    })) << text;
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
    ASSERT_TRUE(result.quality.contraction);
    EXPECT_EQ(result.quality.contraction->stopReason, StopReason::IterationLimit);
    const std::vector<QualityWarning> warnings = result.quality.warnings();
    ASSERT_FALSE(warnings.empty());
    EXPECT_EQ(warnings.front().kind, QualityWarning::Kind::IterationLimit);
    EXPECT_TRUE(warnings.front().problem.suggests(Remedy::raise(Parameter::MaxIterations)));
    const std::string text = describe(warnings.front().problem);
    EXPECT_NE(text.find("maximum iterations"), std::string::npos) << text;
}

namespace {

std::optional<QualityWarning> uncontractedWarning(const SkeletonQuality& q) {
    for (const QualityWarning& w : q.warnings()) {
        if (w.kind == QualityWarning::Kind::UncontractedPoints) return w;
    }
    return std::nullopt;
}

// A flat square plate: the cotangent Laplacian moves a plane only at its edges, so the
// contraction converges with the plate's middle left a flat cloud.
PointList flatPlate() {
    return shapes::sample(shapes::sheet([](double u, double v) { return Point(u, v, 0.0); }, 20, 20), 4000, 3);
}

// Thinning takes the points where contraction left them: the sheets step would move the
// plate onto its medial axis, and these tests are about the points contraction left.
SkeletonParameters withoutSheets() {
    SkeletonParameters p;
    p.graph.collapseSheets = false;
    return p;
}

}  // namespace

TEST(QualityReport, PointsOfAConvergedContractionThatStayedAreNotToldToIterateMore) {
    const PointList plate = flatPlate();
    const SkeletonResult result = computeCurveSkeleton(plate, withoutSheets());
    ASSERT_TRUE(result.quality.contraction);
    ASSERT_EQ(result.quality.contraction->stopReason, StopReason::Converged);
    const std::optional<QualityWarning> warning = uncontractedWarning(result.quality);
    ASSERT_TRUE(warning) << describe(result.quality);
    EXPECT_FALSE(warning->problem.suggests(Remedy::raise(Parameter::MaxIterations))) << describe(warning->problem);
    EXPECT_TRUE(warning->problem.suggests(Remedy::lower(Parameter::ContractionScale))) << describe(warning->problem);
    EXPECT_NE(describe(warning->problem).find("converged"), std::string::npos) << describe(warning->problem);

    // What the warning says: a higher iteration limit leaves the same points uncontracted.
    SkeletonParameters moreIterations = withoutSheets();
    moreIterations.contraction.maxIterations = 4 * result.quality.contraction->iterations;
    const SkeletonResult again = computeCurveSkeleton(plate, moreIterations);
    EXPECT_EQ(again.quality.contraction->iterations, result.quality.contraction->iterations);
    EXPECT_EQ(again.quality.uncontractedPoints, result.quality.uncontractedPoints);
}

TEST(QualityReport, PointsLeftByTheIterationLimitAreToldToIterateMore) {
    SkeletonParameters oneIteration = withoutSheets();
    oneIteration.contraction.maxIterations = 1;
    const SkeletonResult result = computeCurveSkeleton(flatPlate(), oneIteration);
    ASSERT_EQ(result.quality.contraction->stopReason, StopReason::IterationLimit);
    const std::optional<QualityWarning> warning = uncontractedWarning(result.quality);
    ASSERT_TRUE(warning) << describe(result.quality);
    EXPECT_TRUE(warning->problem.suggests(Remedy::raise(Parameter::MaxIterations))) << describe(warning->problem);
}

TEST(QualityReport, RefinementIsReportedWhenOn) {
    SkeletonParameters refine;
    refine.graph.refine = true;
    const SkeletonResult result = computeCurveSkeleton(shapes::torus(4000, 1.0, 0.3), refine);
    EXPECT_TRUE(result.quality.refinement);
    EXPECT_EQ(result.quality.topology.cycles, 1) << "refinement must keep a real loop";
    EXPECT_NE(describe(result.quality).find("Refinement: removed"), std::string::npos);
}
