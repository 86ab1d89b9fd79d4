// Sheets onto their medial axes: a one-sided plate with two holes gives a loop around each
// hole and no hub, also when a grazing scan samples it in bands, when it is sparse or
// noisy; a disc one node at its centre, and a noisy disc moves as a whole; tubes, a thick
// closed plate, a narrow leaf and the flat middle of a cup are left to contraction; the
// paper's pipeline does without.
#include <pcskeleton/skeleton/sheet_collapse.h>
#include <pcskeleton/curve_skeleton.h>
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pcskeleton;

namespace {

constexpr std::size_t kPoints = 6000;

// A square plate 1.6 wide in the plane z = 0, with round holes of radius 0.25 around
// (0.45, 0.8) and (1.15, 0.8), one layer of `points` points.
PointList plateWithTwoHoles(std::uint32_t seed, std::size_t points = kPoints) {
    return shapes::sample(shapes::sheet([](double u, double v) { return Point(1.6 * u, 1.6 * v, 0); }, 64, 64,
                                        [](double u, double v) {
                                            return std::hypot(u - 0.28, v - 0.5) > 0.16 &&
                                                   std::hypot(u - 0.72, v - 0.5) > 0.16;
                                        }),
                          points, seed);
}

PointList disc(double radius, std::uint32_t seed) {
    return shapes::sample(shapes::sheet([radius](double u, double v) {
                              return Point(radius * u * std::cos(2 * M_PI * v), radius * u * std::sin(2 * M_PI * v), 0);
                          }, 24, 96),
                          kPoints, seed);
}

// The surface of a closed box `width` x `width` x `thickness`: two parallel faces and a rim.
PointList closedBox(double width, double thickness, std::uint32_t seed) {
    shapes::Triangles box;
    const auto add = [&box](const std::function<Point(double, double)>& map) {
        const shapes::Triangles face = shapes::sheet(map, 32, 32);
        box.insert(box.end(), face.begin(), face.end());
    };
    for (double z : {0.0, thickness}) add([=](double u, double v) { return Point(width * u, width * v, z); });
    for (double y : {0.0, width}) add([=](double u, double v) { return Point(width * u, y, thickness * v); });
    for (double x : {0.0, width}) add([=](double u, double v) { return Point(x, width * u, thickness * v); });
    return shapes::sample(box, kPoints, seed);
}

}  // namespace

TEST(SheetCollapse, APlateGivesALoopAroundEachHoleAndNoHub) {
    for (std::uint32_t seed : {1u, 2u}) {
        const SkeletonResult r = computeCurveSkeleton(plateWithTwoHoles(seed));
        ASSERT_TRUE(r.quality.sheets);
        EXPECT_EQ(r.quality.sheets->patches, 1) << "seed " << seed;
        const SkeletonTopology t = analyseTopology(r.skeleton);
        EXPECT_EQ(t.cycles, 2) << describe(t) << ", seed " << seed;
        EXPECT_LE(t.tips, 2) << describe(t) << ", seed " << seed;
        // On the plate, around the holes: no node in a hole, none off the plane.
        for (const Point& node : r.skeleton.nodes) {
            EXPECT_NEAR(node.z(), 0.0, 1e-9);
            EXPECT_GT(std::hypot(node.x() - 0.45, node.y() - 0.8), 0.25);
            EXPECT_GT(std::hypot(node.x() - 1.15, node.y() - 0.8), 0.25);
        }
    }
    // Without it, thinning makes the plate's flat middle a hub of long bones to its rim.
    SkeletonParameters off;
    off.graph.collapseSheets = false;
    const SkeletonResult hub = computeCurveSkeleton(plateWithTwoHoles(1), off);
    EXPECT_FALSE(hub.quality.sheets);
    EXPECT_GT(analyseTopology(hub.skeleton).tips, 2) << describe(analyseTopology(hub.skeleton));
}

TEST(SheetCollapse, APlateScannedAtAGrazingAngleKeepsOnlyItsOwnHoles) {
    // Seen 15 degrees above its plane (the robustness suite's view from the side, turned to
    // this plate), the plate comes back in bands, one per row of the scanner's pixels, with
    // empty bands between them: gaps in the sampling, not holes. Closed only over the gaps
    // into which a disc of one thinning radius did not fit, the plate had a false third loop
    // on each of these four samples; it still has one on one of them.
    const double area = 1.6 * 1.6 - 2 * M_PI * 0.25 * 0.25;
    int right = 0;
    for (std::uint32_t seed : {1u, 2u, 3u, 4u}) {
        const PointList scan = shapes::visibleFrom(plateWithTwoHoles(seed, 2 * kPoints), Point(1, -0.55, -0.3),
                                                   3 * std::sqrt(area / (2 * kPoints)));
        const SkeletonResult r = computeCurveSkeleton(scan);
        ASSERT_TRUE(r.quality.sheets);
        EXPECT_EQ(r.quality.sheets->patches, 1) << "seed " << seed;
        const SkeletonTopology t = analyseTopology(r.skeleton);
        EXPECT_GE(t.cycles, 2) << describe(t) << ", seed " << seed;  // the plate's own holes stay
        EXPECT_EQ(t.components, 1) << describe(t) << ", seed " << seed;
        right += t.cycles == 2;
    }
    EXPECT_GE(right, 3);
}

// Noise of 1.5% of the diagonal hides the plane within two thinning radii of most points;
// the copy that denoising gives the contraction shows it again. Judged on the noisy points,
// the plate was no sheet on any of these seeds.
TEST(SheetCollapse, ANoisyPlateIsJudgedAsDenoisedAndKeepsItsHoles) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        const SkeletonResult r = computeCurveSkeleton(shapes::withNoise(plateWithTwoHoles(seed), 0.015, seed));
        ASSERT_GT(r.contraction.denoisingPasses, 0) << "seed " << seed;
        ASSERT_TRUE(r.quality.sheets);
        EXPECT_EQ(r.quality.sheets->patches, 1) << "seed " << seed;
        const SkeletonTopology t = analyseTopology(r.skeleton);
        EXPECT_EQ(t.cycles, 2) << describe(t) << ", seed " << seed;
        EXPECT_EQ(t.components, 1) << describe(t) << ", seed " << seed;
    }
}

// With 2% noise the sheet test passes on only part of a disc, even denoised. The points it
// leaves out within the plate's own noise of its plane join the plate: left where
// contraction put them, their 1-rings tied them to the points on the axis in a web of bones.
// Before, 50% to 88% of these discs' points were moved.
TEST(SheetCollapse, ANoisyDiscMovesAllItsPointsTogether) {
    for (std::uint32_t seed : {1u, 2u, 6u, 7u}) {
        const SkeletonResult r = computeCurveSkeleton(shapes::withNoise(disc(0.8, seed), 0.02, seed));
        ASSERT_TRUE(r.quality.sheets);
        EXPECT_EQ(r.quality.sheets->patches, 1) << "seed " << seed;
        EXPECT_GE(r.quality.sheets->points, std::size_t(0.98 * kPoints)) << "seed " << seed;
    }
}

TEST(SheetCollapse, ADiscGathersAtItsCentre) {
    // Its medial axis is its centre (on a grid, the thinning can wear a round shape away to
    // nothing: then its deepest cell stands for it).
    for (std::uint32_t seed : {3u, 4u}) {
        const SkeletonResult r = computeCurveSkeleton(disc(0.8, seed));
        const SkeletonTopology t = analyseTopology(r.skeleton);
        EXPECT_EQ(t.cycles, 0) << describe(t);
        EXPECT_EQ(t.components, 1) << describe(t);
        for (const Point& node : r.skeleton.nodes) EXPECT_LT(node.norm(), 0.1) << describe(t);
    }
}

TEST(SheetCollapse, TubesAThickClosedPlateAndANarrowLeafAreLeftToContraction) {
    // A tube whose wall is flat at the sheet test's scale: its strips narrow as it contracts.
    const SkeletonResult tube = computeCurveSkeleton(shapes::cylinder(kPoints, 0.4, 1.6, true, 4));
    ASSERT_TRUE(tube.quality.sheets);
    EXPECT_EQ(tube.quality.sheets->patches, 0);
    // Each face of a closed plate has the other face across it.
    const SkeletonResult box = computeCurveSkeleton(closedBox(1.6, 0.3, 5));
    ASSERT_TRUE(box.quality.sheets);
    EXPECT_EQ(box.quality.sheets->patches, 0);
    // A leaf blade 0.2 wide: narrower than the patches moved.
    const PointList blade = shapes::sample(
        shapes::sheet([](double u, double v) { return Point(1.6 * u, 0.2 * v, 0.3 * std::sin(M_PI * u)); }, 64, 8),
        kPoints, 6);
    const SkeletonResult leaf = computeCurveSkeleton(blade);
    ASSERT_TRUE(leaf.quality.sheets);
    EXPECT_EQ(leaf.quality.sheets->patches, 0);
}

// A cup 1.6 across whose rim rises 45 degrees (a cupped leaf, as the paper's tobacco):
// its middle, within 30 degrees of flat, is a wide flat patch, but it goes on into sheet
// points that face another way. It is no plate: its points are left to contraction.
TEST(SheetCollapse, TheFlatMiddleOfACupIsLeftToContraction) {
    const PointList cup = shapes::sample(shapes::sheet([](double u, double v) {
                                             const double r = 0.8 * u, a = 2 * M_PI * v;
                                             return Point(r * std::cos(a), r * std::sin(a), 0.625 * r * r);
                                         }, 24, 96),
                                         kPoints, 7);
    const SkeletonResult r = computeCurveSkeleton(cup);
    ASSERT_TRUE(r.quality.sheets);
    EXPECT_EQ(r.quality.sheets->patches, 0);
}

TEST(SheetCollapse, ThePapersPipelineThinsTheContractedPointsAsTheyAre) {
    const SkeletonResult r = computeCurveSkeleton(plateWithTwoHoles(1), SkeletonParameters::paper());
    EXPECT_FALSE(r.quality.sheets);
    EXPECT_NE(describe(r.quality).find("Sheets: off."), std::string::npos);
}

// 600 points: a ball of two thinning radii holds about 10 of them, often fewer; the nearest
// ten then judge the plane (docs/benchmarks.md, "Sparse clouds").
TEST(SheetCollapse, ASparsePlateIsStillOnePatchWithItsTwoHoles) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        const SkeletonResult r = computeCurveSkeleton(plateWithTwoHoles(seed, 600));
        ASSERT_TRUE(r.quality.sheets);
        EXPECT_EQ(r.quality.sheets->patches, 1) << "seed " << seed;
        const SkeletonTopology t = analyseTopology(r.skeleton);
        EXPECT_EQ(t.cycles, 2) << describe(t) << ", seed " << seed;
    }
}
