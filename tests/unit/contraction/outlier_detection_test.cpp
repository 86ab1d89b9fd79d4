// Outlier detection on clouds whose outliers are known: points scattered around a torus,
// a small far cluster; and what must stay: a real separate part, unevenly dense surfaces.
#include <pcskeleton/core/errors.h>
#include <pcskeleton/contraction/outlier_detection.h>
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"

#include <gtest/gtest.h>

#include <numeric>

namespace pcskeleton {
namespace {

std::size_t flaggedIn(const std::vector<char>& flags, std::size_t from, std::size_t to) {
    return std::size_t(std::accumulate(flags.begin() + std::ptrdiff_t(from), flags.begin() + std::ptrdiff_t(to), 0));
}

TEST(OutlierDetection, ScatteredPointsAroundATorusAreFoundAndTheTorusIsNot) {
    const PointList torus = shapes::torus(6000, 1.0, 0.3);
    const PointList cloud = shapes::withOutliers(torus, 0.05, 3);  // 300 points in the box
    const std::vector<char> flags = findOutliers(cloud, {});
    EXPECT_EQ(flaggedIn(flags, 0, torus.size()), 0u);
    // Nine in ten of those more than half the tube's radius off the surface are found (the
    // rest sit in pairs or clumps, and look like a sparse bit of surface to each other).
    std::size_t far = 0, farFound = 0;
    for (std::size_t i = torus.size(); i < cloud.size(); ++i) {
        const Point& p = cloud[i];
        const double offSurface = std::abs(std::hypot(std::hypot(p.x(), p.y()) - 1.0, p.z()) - 0.3);
        if (offSurface > 0.15) ++far, farFound += flags[i];
    }
    EXPECT_GT(far, 150u);
    EXPECT_GE(double(farFound), 0.9 * far) << farFound << " of " << far;  // measured: 146 of 160
}

TEST(OutlierDetection, ASmallFarClusterIsFoundARealSeparatePartIsNot) {
    PointList cloud = shapes::torus(6000, 1.0, 0.3);
    const std::size_t torus = cloud.size();
    for (const Point& p : shapes::sphere(400, 0.15, 5)) cloud.push_back(p + Point(3.0, 0, 0));  // 6%: a part
    const std::size_t part = cloud.size();
    for (const Point& p : shapes::sphere(20, 0.05, 7)) cloud.push_back(p + Point(0, 3.0, 0));   // 0.3%: a clump
    const std::vector<char> flags = findOutliers(cloud, {});
    EXPECT_EQ(flaggedIn(flags, 0, torus), 0u);
    EXPECT_EQ(flaggedIn(flags, torus, part), 0u);
    EXPECT_EQ(flaggedIn(flags, part, cloud.size()), 20u);
}

TEST(OutlierDetection, UnevenDensityIsNotTakenForOutliers) {
    // Half of the points in a tenth of the surface: the rest is three times sparser.
    const PointList uneven = shapes::unevenlyDense(shapes::sphere(30000, 1.0, 2), 6000, 0.1, 3);
    const std::vector<char> flags = findOutliers(uneven, {});
    EXPECT_EQ(flaggedIn(flags, 0, uneven.size()), 0u);
}

TEST(OutlierDetection, TheRuleIsScaleFree) {
    const PointList cloud = shapes::withOutliers(shapes::torus(3000, 1.0, 0.3), 0.02, 4);
    PointList scaled;
    for (const Point& p : cloud) scaled.push_back(p * 1e4 + Point(5e5, -3e5, 0));
    const std::vector<char> flags = findOutliers(cloud, {});
    EXPECT_GT(flaggedIn(flags, 0, cloud.size()), 0u);
    EXPECT_EQ(findOutliers(scaled, {}), flags);
}

// A cloud larger than the statistics sample: the tests run on a sample, every other point
// is judged by the sample's passing points around it. The torus and a real part are kept, a
// far clump found; of the scattered points, those farther off the surface than the
// sample's isolation distance (0.3 with a fifth of the points as the sample; with all of
// them, 0.1) are all found. The answer does not depend on the order of the points.
TEST(OutlierDetection, ACloudLargerThanTheSampleIsJudgedThroughItWithTheSameAnswers) {
    PointList cloud = shapes::withOutliers(shapes::torus(40000, 1.0, 0.3), 0.05, 3);
    const std::size_t torus = 40000, scattered = cloud.size();
    for (const Point& p : shapes::sphere(2400, 0.15, 5)) cloud.push_back(p + Point(3.0, 0, 0));  // 5%: a part
    const std::size_t part = cloud.size();
    for (const Point& p : shapes::sphere(60, 0.05, 7)) cloud.push_back(p + Point(0, 3.0, 0));  // a clump
    OutlierParameters sampled;
    sampled.statisticsSample = 8000;
    const std::vector<char> flags = findOutliers(cloud, sampled);
    EXPECT_EQ(flaggedIn(flags, 0, torus), 0u);
    EXPECT_EQ(flaggedIn(flags, scattered, part), 0u);
    EXPECT_EQ(flaggedIn(flags, part, cloud.size()), 60u);
    std::size_t far = 0, farFound = 0;
    for (std::size_t i = torus; i < scattered; ++i) {
        const Point& p = cloud[i];
        const double offSurface = std::abs(std::hypot(std::hypot(p.x(), p.y()) - 1.0, p.z()) - 0.3);
        if (offSurface > 0.3) ++far, farFound += flags[i];
    }
    EXPECT_GT(far, 500u);
    EXPECT_EQ(farFound, far);

    const PointList reversed(cloud.rbegin(), cloud.rend());
    const std::vector<char> reversedFlags = findOutliers(reversed, sampled);
    EXPECT_TRUE(std::equal(flags.begin(), flags.end(), reversedFlags.rbegin()));

    // At the sample's size the whole cloud is tested, as below it.
    OutlierParameters whole;
    whole.statisticsSample = cloud.size();
    EXPECT_EQ(flaggedIn(findOutliers(cloud, whole), part, cloud.size()), 60u);
}

TEST(OutlierDetection, OffOrTooFewPointsFlagsNothing) {
    const PointList cloud = shapes::withOutliers(shapes::torus(3000, 1.0, 0.3), 0.02, 4);
    OutlierParameters off;
    off.detect = false;
    EXPECT_EQ(flaggedIn(findOutliers(cloud, off), 0, cloud.size()), 0u);
    const PointList few(cloud.begin(), cloud.begin() + 10);
    EXPECT_EQ(flaggedIn(findOutliers(few, {}), 0, few.size()), 0u);
}

TEST(OutlierDetection, UnusableParametersAreRefusedByName) {
    OutlierParameters p;
    p.isolationFactor = 0.5;
    try {
        findOutliers(shapes::sphere(100, 1.0), p);
        ADD_FAILURE() << "isolation factor 0.5 accepted";
    } catch (const InvalidInput& e) {
        EXPECT_EQ(e.problem().subject, Parameter::OutlierIsolation);
    }
    p = {};
    p.clusterShare = 0.7;
    EXPECT_THROW(findOutliers(shapes::sphere(100, 1.0), p), InvalidInput);
    p = {};
    p.statisticsSample = 10;  // no statistics in ten points: a programming error, not input
    EXPECT_THROW(findOutliers(shapes::sphere(100, 1.0), p), CallerError);
}

}  // namespace
}  // namespace pcskeleton
