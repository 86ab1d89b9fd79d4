// Noise-adaptive weights of the surface term, and what they do to a noisy scan's surface.
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"
#include <pcskeleton/reconstruction/point_weights.h>
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace pcskeleton;

namespace {

// n points on the unit square of the z = 0 plane, moved across it by Gaussian noise of `sigma`.
PointList squareScan(std::size_t n, double sigma, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, sigma);
    PointList points;
    for (std::size_t i = 0; i < n; ++i) points.emplace_back(unit(random), unit(random), sigma > 0 ? noise(random) : 0.0);
    return points;
}


}  // namespace

TEST(PointWeights, CleanPointsKeepTheSurfaceWeight) {
    const SurfacePointWeights w = noiseAdaptedWeights(squareScan(4000, 0.0, 1), 0.02, 5.0);
    ASSERT_EQ(w.weight.size(), 4000u);
    for (double weight : w.weight) EXPECT_NEAR(weight, 5.0, 1e-9);
    EXPECT_NEAR(w.meanShare, 1.0, 1e-12);
}

TEST(PointWeights, PointsScatteredByCellsWeighLess) {
    const double cell = 0.02;
    const SurfacePointWeights halfCell = noiseAdaptedWeights(squareScan(4000, 0.5 * cell, 2), cell, 5.0);
    const SurfacePointWeights twoCells = noiseAdaptedWeights(squareScan(4000, 2.0 * cell, 3), cell, 5.0);
    EXPECT_GT(halfCell.meanShare, 0.9);
    EXPECT_LT(twoCells.meanShare, 0.8);
    EXPECT_LT(twoCells.meanShare, halfCell.meanShare);
    for (double weight : twoCells.weight) {
        EXPECT_GT(weight, 0.0);
        EXPECT_LE(weight, 5.0);
    }
}

TEST(PointWeights, ANoisyTubesSurfaceStaysCloserToItsWall) {
    // A tube of radius 0.3 and length 2, with noise of 2% of its diagonal (about 0.043, a
    // seventh of the radius), and its axis as the skeleton.
    const shapes::Polyline axis = {{Point(0, 0, 0), Point(0, 0, 2)}};
    const PointList scan = shapes::withNoise(shapes::tube(axis, 0.3, 6000, 4), 0.02, 4);
    const SkeletonGraph skeleton = shapes::curveSkeleton(axis, 0.3);
    ReconstructionParameters parameters;
    parameters.resolution = 128;  // cells of 0.016: the noise spans about 3
    const Reconstruction adapted = reconstructFromSkeleton(scan, skeleton, parameters);
    parameters.adaptToNoise = false;
    const Reconstruction uniform = reconstructFromSkeleton(scan, skeleton, parameters);

    EXPECT_LT(adapted.report.surfaceWeightShare, 0.9);
    EXPECT_DOUBLE_EQ(uniform.report.surfaceWeightShare, 1.0);
    EXPECT_EQ(adapted.report.topology.genus, 0);
    EXPECT_EQ(adapted.report.topology.components, 1);
    const double adaptedDistance = shapes::meanDistanceToCylinderWall(adapted.mesh.vertices, 0.3, 0.4, 1.6);
    const double uniformDistance = shapes::meanDistanceToCylinderWall(uniform.mesh.vertices, 0.3, 0.4, 1.6);
    EXPECT_LT(adaptedDistance, 0.9 * uniformDistance) << adaptedDistance << " vs " << uniformDistance;
    std::printf("mean distance to the wall: %.4f adapted, %.4f uniform\n", adaptedDistance, uniformDistance);
}
