// Denoising before contraction: the noise measure tells clean from noisy at any scale,
// the denoised copy is closer to the true surface, and a noisy ring keeps its one cycle.
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"
#include <pcskeleton/contraction/point_denoising.h>
#include <pcskeleton/curve_skeleton.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace pcskeleton;

namespace {

// The mean and the spread of the points' distances to the sphere's centre.
struct Radii {
    double mean = 0, spread = 0;
};
Radii radiiOf(const PointList& points) {
    Radii r;
    for (const Point& p : points) r.mean += p.norm();
    r.mean /= double(points.size());
    for (const Point& p : points) r.spread += std::pow(p.norm() - r.mean, 2);
    r.spread = std::sqrt(r.spread / double(points.size()));
    return r;
}

}  // namespace

TEST(PointDenoising, SurfaceNoiseTellsCleanFromNoisyAtAnyScale) {
    const PointList clean = shapes::sphere(4000, 1.0);
    const PointList noisy = shapes::withNoise(clean, 0.02);  // 2% of the diagonal
    EXPECT_LT(surfaceNoise(clean, 30), 0.02);
    EXPECT_GT(surfaceNoise(noisy, 30), kNoisySurface);
    // A coarse clean sampling is still clean: the quadric follows the curvature.
    EXPECT_LT(surfaceNoise(shapes::torus(400, 1.0, 0.3), 8), kNoisySurface);
    PointList large = noisy;
    for (Point& p : large) p *= 1000.0;
    EXPECT_NEAR(surfaceNoise(large, 30), surfaceNoise(noisy, 30), 1e-9);
}

// The noise across the surface goes; what is left is a slight shrinking (each plane cuts
// the sphere's curvature), which the contraction does not mind: it shrinks anyway.
TEST(PointDenoising, TheNoiseAcrossTheSurfaceGoesCleanPointsBarelyMove) {
    const PointList clean = shapes::sphere(4000, 1.0);
    const PointList noisy = shapes::withNoise(clean, 0.01);
    const Radii before = radiiOf(noisy), after = radiiOf(denoisedCopy(noisy, 30, 2));
    EXPECT_LT(after.spread, before.spread / 3) << before.spread << " -> " << after.spread;
    const Radii cleaned = radiiOf(denoisedCopy(clean, 30, 2));
    EXPECT_GT(cleaned.mean, 0.98);
    EXPECT_LT(cleaned.spread, 0.005);
    EXPECT_EQ(denoisedCopy(noisy, 30, 0), noisy);
}

TEST(PointDenoising, AutomaticOnlyForNoisyCloudsAndPassesInRange) {
    const PointList clean = shapes::sphere(4000, 1.0);
    EXPECT_EQ(chooseDenoising(clean, 30, kAutomaticDenoising).passes, 0);
    EXPECT_EQ(chooseDenoising(shapes::withNoise(clean, 0.02), 30, kAutomaticDenoising).passes, kPassesForNoisySurface);
    EXPECT_EQ(chooseDenoising(clean, 30, 3).passes, 3);
    EXPECT_LT(chooseDenoising(clean, 30, 3).surfaceNoise, 0) << "not measured when the passes are given";
    for (int wrong : {-2, 11}) {
        try {
            chooseDenoising(clean, 30, wrong);
            FAIL() << wrong << " passes were accepted";
        } catch (const InvalidInput& e) {
            EXPECT_EQ(e.problem().subject, Parameter::DenoisingPasses);
        }
    }
}

// A ring-shaped tube with noise of 2% of the diagonal: one cycle and no tip by default;
// the report says it was denoised.
TEST(PointDenoising, ANoisyRingKeepsItsCycleWithoutSpurs) {
    const PointList ring = shapes::withNoise(shapes::tube(shapes::circle(Point::Zero(), 0.8), 0.15, 6000), 0.02);
    const SkeletonResult result = computeCurveSkeleton(ring, SkeletonParameters{});
    EXPECT_EQ(result.quality.topology.cycles, 1) << describe(result.quality.topology);
    EXPECT_EQ(result.quality.topology.tips, 0) << describe(result.quality.topology);
    ASSERT_TRUE(result.quality.contraction);
    EXPECT_EQ(result.quality.contraction->denoisingPasses, kPassesForNoisySurface);
    EXPECT_GT(result.quality.contraction->surfaceNoise, kNoisySurface);
    EXPECT_NE(describeFindings(result.quality).find("Denoising: 2 passes on the contracted copy (automatic: surface noise"),
              std::string::npos);
}
