// The medial pull: each point's medial centre from a shrinking ball on its inner side, none
// where the inside is open, and a narrow hole that contraction alone closes kept open.
#include <pcskeleton/contraction/medial_pull.h>
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/skeleton/skeleton_structure.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace pcskeleton;

namespace {

// Distance from p to the circle of radius `major` about the z axis in the z = 0 plane.
double distanceToAxisCircle(const Point& p, double major) {
    return std::hypot(std::hypot(p.x(), p.y()) - major, p.z());
}

}  // namespace

TEST(MedialPull, ATorusPointsMedialCentresLieOnItsTubesAxis) {
    const double major = 1.0, minor = 0.3;
    const PointList points = shapes::torus(6000, major, minor);
    const MedialTargets targets = estimateMedialTargets(points);
    ASSERT_EQ(targets.centres.size(), points.size());
    // A closed surface: every point's inside closes.
    EXPECT_GT(targets.count, points.size() * 95 / 100);
    std::vector<double> offAxis;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (targets.found[i]) offAxis.push_back(distanceToAxisCircle(targets.centres[i], major));
    }
    std::sort(offAxis.begin(), offAxis.end());
    // Points are about 0.045 apart: the ball closes on a point near the far wall, within a
    // spacing of the axis.
    EXPECT_LT(offAxis[offAxis.size() / 2], 0.15 * minor);
    EXPECT_LT(offAxis[offAxis.size() * 9 / 10], 0.3 * minor);
}

TEST(MedialPull, ASheetSeenFromOneSideHasNoMedialCentres) {
    // A disc of radius 0.8, sampled on one layer (as a scanner sees a plate from above).
    const PointList disc = shapes::sample(
        shapes::sheet([](double u, double v) { return Point(1.6 * u - 0.8, 1.6 * v - 0.8, 0); }, 64, 64,
                      [](double u, double v) { return std::hypot(u - 0.5, v - 0.5) < 0.5; }),
        3000);
    const MedialTargets targets = estimateMedialTargets(disc);
    EXPECT_EQ(targets.count, 0u);
    EXPECT_TRUE(targets.empty());
}

TEST(MedialPull, KeepsTheLoopOfARingWhoseHoleIsNarrowNextToItsTube) {
    // The hole is 0.28 across, the tube 0.72 thick: contraction alone flattens the ring into
    // a disc and loses the loop (docs/benchmarks.md, "A thick ring loses its hole").
    const PointList ring = shapes::torus(6000, 0.5, 0.36);
    SkeletonParameters pulled;
    pulled.contraction.medialPull = 1.0;
    const SkeletonTopology withPull = analyseTopology(computeCurveSkeleton(ring, pulled).skeleton);
    EXPECT_EQ(withPull.components, 1) << describe(withPull);
    EXPECT_EQ(withPull.cycles, 1) << describe(withPull);
    EXPECT_EQ(withPull.tips, 0) << describe(withPull);

    SkeletonParameters unpulled = pulled;
    unpulled.contraction.medialPull = 0;
    EXPECT_EQ(analyseTopology(computeCurveSkeleton(ring, unpulled).skeleton).cycles, 0);
}
