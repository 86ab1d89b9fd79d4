// The robustness suite's scan defects do what they say.
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pcskeleton;

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
