// The multi-resolution subsample: at most the target, well spread, every point stood for
// by a kept point of its own cube, outliers left out, the same every run.
#include <pcskeleton/contraction/point_subsampling.h>
#include <pcskeleton/core/errors.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

using namespace pcskeleton;

TEST(PointSubsampling, KeepsAtMostTheTargetAndEveryPointHasAKeeperInItsCube) {
    const PointList cloud = shapes::torus(60000, 1.0, 0.3, 3);
    const PointSubsample s = spreadSubsample(cloud, 5000);
    EXPECT_LE(s.kept.size(), 5000u);
    EXPECT_GT(s.kept.size(), 4000u) << "the cube size search should come close to the target";
    EXPECT_TRUE(std::is_sorted(s.kept.begin(), s.kept.end()));
    ASSERT_EQ(s.keeperOf.size(), cloud.size());
    const double cubeDiagonal = std::sqrt(3.0) * s.cellSize;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        ASSERT_GE(s.keeperOf[i], 0);
        ASSERT_LT(s.keeperOf[i], int(s.kept.size()));
        ASSERT_LE((cloud[i] - cloud[s.kept[s.keeperOf[i]]]).norm(), cubeDiagonal * (1 + 1e-9)) << "point " << i;
    }
    // A kept point stands for itself.
    for (std::size_t k = 0; k < s.kept.size(); ++k) EXPECT_EQ(s.keeperOf[s.kept[k]], int(k));
}

// Half of the points crowd into a tenth of the tube: the grid keeps an even spread, so the
// dense end does not take half of the subsample.
TEST(PointSubsampling, EvensOutTheDensity) {
    PointList cloud = shapes::cylinder(20000, 0.1, 0.1, false, 1);
    for (const Point& p : shapes::cylinder(20000, 0.1, 1.0, false, 2)) {
        if (p.z() > 0.1) cloud.push_back(p);
    }
    const PointSubsample s = spreadSubsample(cloud, 3000);
    const auto dense = std::count_if(s.kept.begin(), s.kept.end(), [&](int i) { return cloud[i].z() <= 0.1; });
    EXPECT_LT(double(dense) / double(s.kept.size()), 0.2) << dense << " of " << s.kept.size() << " kept in the dense tenth";
}

TEST(PointSubsampling, LeavesOutFlaggedPointsAndIsDeterministic) {
    PointList cloud = shapes::sphere(30000, 1.0, 5);
    std::vector<char> leaveOut(cloud.size(), 0);
    for (std::size_t i = 0; i < cloud.size(); i += 10) leaveOut[i] = 1;
    const PointSubsample a = spreadSubsample(cloud, 2000, leaveOut), b = spreadSubsample(cloud, 2000, leaveOut);
    EXPECT_EQ(a.kept, b.kept);
    EXPECT_EQ(a.keeperOf, b.keeperOf);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        if (leaveOut[i]) EXPECT_EQ(a.keeperOf[i], -1) << "point " << i;
        else EXPECT_GE(a.keeperOf[i], 0) << "point " << i;
    }
    for (int k : a.kept) EXPECT_FALSE(leaveOut[k]);
}

// The same points kept whatever the order of the input: the cube size is searched on a
// sample chosen by coordinates (a cloud this much larger than the target is searched on a
// sample), and the points of a regular grid, as near to their cube's centre as each other,
// are told apart by their coordinates.
TEST(PointSubsampling, TheKeptPointsDependOnThePointsNotOnTheirOrder) {
    PointList grid;
    for (int x = 0; x < 200; ++x)
        for (int y = 0; y < 150; ++y) grid.push_back(Point(x, y, 0.25 * (x % 2)));
    std::vector<std::size_t> order(grid.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(3));
    PointList shuffled;
    for (std::size_t i : order) shuffled.push_back(grid[i]);

    const PointSubsample a = spreadSubsample(grid, 200), b = spreadSubsample(shuffled, 200);
    ASSERT_EQ(a.kept.size(), b.kept.size());
    EXPECT_EQ(a.cellSize, b.cellSize);
    for (std::size_t k = 0; k < order.size(); ++k) {
        ASSERT_EQ(shuffled[std::size_t(b.kept[std::size_t(b.keeperOf[k])])], grid[std::size_t(a.kept[std::size_t(a.keeperOf[order[k]])])])
            << "grid point " << order[k];
    }
}

TEST(PointSubsampling, SmallCloudsAreKeptWhole) {
    const PointList cloud = shapes::sphere(800, 1.0);
    const PointSubsample s = spreadSubsample(cloud, 1000);
    ASSERT_EQ(s.kept.size(), cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_EQ(s.keeperOf[i], int(i));
    EXPECT_THROW(spreadSubsample(cloud, 0), CallerError);
}
