// A node stays with its data: the invariant itself, and known answers where re-centring
// used to break it: sheets seen from one side (a flat disc, a slightly curved plate, the
// paper's corn plant) keep every node on the sheet, while a half tube is still re-centred.
#include <pcskeleton/finishing/data_support.h>
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/io/point_cloud_io.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pcskeleton;

namespace {

// Distance from `p` to the nearest of `points`, by brute force.
double nearestDistance(const Point& p, const PointList& points) {
    double nearest = INFINITY;
    for (const Point& q : points) nearest = std::min(nearest, (q - p).norm());
    return nearest;
}

// Every node of the skeleton inside the points' bounding box (grown by the support's slack),
// within `share` of the diagonal of some point (share 0: not checked), and none reported
// away from its data.
void expectNodesOnTheData(const SkeletonResult& result, const PointList& points, double share) {
    Eigen::AlignedBox3d box = boundingBox(points);
    const double diagonal = box.diagonal().norm();
    const double slack = kSupportSlack * result.quality.nodeSpacing;
    box.min().array() -= slack;
    box.max().array() += slack;
    for (std::size_t n = 0; n < result.skeleton.nodeCount(); ++n) {
        const Point& node = result.skeleton.nodes[n];
        EXPECT_TRUE(box.contains(node)) << "node " << n << " outside the points' bounding box";
        if (share > 0) EXPECT_LE(nearestDistance(node, points), share * diagonal) << "node " << n;
    }
    EXPECT_TRUE(result.quality.nodesAwayFromData.empty()) << describe(result.quality);
}

// A sheet of n points: (x, y) uniform in [0, length] x [-width/2, width/2], bent about the
// x axis onto a circle of radius `bend` (0: flat).
PointList sheet(std::size_t n, double length, double width, double bend, std::uint32_t seed = 1) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> along(0, length), across(-width / 2, width / 2);
    PointList points;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = along(random), y = across(random);
        if (bend == 0) points.emplace_back(x, y, 0.0);
        else points.emplace_back(x, bend * std::sin(y / bend), bend * (1 - std::cos(y / bend)));
    }
    return points;
}

}  // namespace

TEST(DataSupport, ANodeNearItsPointsIsSupportedAndOneAwayIsNot) {
    const PointList points = {Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0), Point(1, 1, 0)};
    const DataSupport support(points, 0.2);  // slack 0.1; the box spans y from -0.1 to 1.1
    EXPECT_TRUE(support.supports(Point(1, 0.05, 0), 0.0, {1}));
    EXPECT_TRUE(support.supports(Point(1, 0.5, 0), 0.45, {1}));   // within its radius plus the slack
    EXPECT_FALSE(support.supports(Point(1, 0.09, 0), 0.0, {0}));  // near a point, but not its own
    EXPECT_FALSE(support.supports(Point(1, 0.3, 0), 0.1, {1}));
    EXPECT_FALSE(support.supports(Point(1, 0.5, 0.5), 1.0, {1}));  // outside the bounding box
    EXPECT_TRUE(support.supports(Point(2.05, 0, 0), 0.0, {}));    // no points of its own: the nearest point
    EXPECT_FALSE(support.supports(Point(2.15, 0.15, 0), 0.0, {}));
    EXPECT_FALSE(support.supports(Point(NAN, 0, 0), 1.0, {1}));
}

TEST(DataSupport, TheUnsupportedNodesOfASkeleton) {
    const PointList points = {Point(0, 0, 0), Point(0.1, 0, 0), Point(1, 0, 0), Point(1.1, 0, 0)};
    SkeletonGraph g;
    g.nodes = {Point(0.05, 0, 0), Point(1.05, 0.8, 0)};
    g.radii = {0.05, 0.05};
    g.edges = {{0, 1}};
    g.pointNode = {0, 0, 1, 1};
    EXPECT_EQ(DataSupport(points, 0.2).unsupportedNodes(g), std::vector<int>{1});
}

TEST(DataSupport, AFlatDiscSeenFromOneSideKeepsItsNodesOnIt) {
    PointList disc;
    for (const Point& p : sheet(12000, 2.0, 2.0, 0.0)) {
        if ((p - Point(1, 0, 0)).norm() <= 1.0) disc.push_back(p);
    }
    const SkeletonResult result = computeCurveSkeleton(disc);
    for (std::size_t n = 0; n < result.skeleton.nodeCount(); ++n) {
        EXPECT_NEAR(result.skeleton.nodes[n].z(), 0.0, 1e-9) << "node " << n << " left the disc's plane";
    }
    expectNodesOnTheData(result, disc, 0.025);
}

TEST(DataSupport, ASlightlyCurvedPlateKeepsItsNodesOnIt) {
    // 1 wide, bent on a circle of radius 3: an arc of 19 degrees, whose circle's centre is 3
    // away, as a leaf seen from either side.
    const PointList plate = sheet(6000, 4.0, 1.0, 3.0);
    const SkeletonResult result = computeCurveSkeleton(plate);
    expectNodesOnTheData(result, plate, 0.02);
    EXPECT_EQ(result.quality.recentering ? result.quality.recentering->recentredNodes : -1, 0);
}

TEST(DataSupport, TheCornPlantsNodesStayOnItsLeaves) {
    // The paper's raw scan of a corn plant (Fig. 7j): thin curled leaves with boundaries,
    // where re-centring used to put nodes beside the leaves, some outside the cloud's box.
    const PointList corn = readPointCloud(PCSKELETON_SCANS_DIR "/corn_v12108.ply");
    ASSERT_EQ(corn.size(), 12108u);
    expectNodesOnTheData(computeCurveSkeleton(corn), corn, 0.025);
}

TEST(DataSupport, TheCornPlantsNodesStayOnItsLeavesAtHalfItsDensity) {
    // Every other point of the same scan. Its leaves, folded along the midrib, fit circles
    // whose neighbours agree, as a tube's wall seen from one side does: re-centring took such
    // nodes off the leaves until it asked each half of the arc to curve as the whole does.
    const PointList corn = readPointCloud(PCSKELETON_SCANS_DIR "/corn_v12108.ply");
    for (std::size_t first : {0, 1}) {
        PointList half;
        for (std::size_t i = first; i < corn.size(); i += 2) half.push_back(corn[i]);
        SCOPED_TRACE("every other point from " + std::to_string(first));
        expectNodesOnTheData(computeCurveSkeleton(half), half, 0.025);
    }
}

TEST(DataSupport, TheTobaccoLeafsNodesStayOnIt) {
    // The paper's raw scan of a tobacco leaf (Fig. 7): broad, cupped, its tip curled. The
    // circles fitted across the curl drift from node to node, and two of them agreed by
    // chance: re-centring took the tip's nodes 5% of the diagonal off the leaf.
    const PointList tobacco = readPointCloud(PCSKELETON_SCANS_DIR "/tobacco_v8098.ply");
    ASSERT_EQ(tobacco.size(), 8098u);
    expectNodesOnTheData(computeCurveSkeleton(tobacco), tobacco, 0.025);
}

TEST(DataSupport, TheReportCountsRefusedMovesAndNamesNodesAwayFromTheirData) {
    SkeletonQuality q;
    q.recentering = RecenteringReport{};
    q.recentering->recentredNodes = 3;
    q.recentering->meanShift = 0.5;
    q.recentering->refused = 2;
    q.recentering->unlikeNeighbours = 4;
    q.recentering->foldedSheets = 1;
    q.tipExtension = TipExtensionReport{};
    q.tipExtension->extendedTips = 1;
    q.tipExtension->refused = 1;
    std::string text = describeFindings(q);
    EXPECT_NE(text.find("Re-centring: 3 nodes of one-sided parts moved, by 0.5 on average; 4 nodes left in place "
                        "(curled like a leaf: no neighbour shows the same tube); 1 node left in place (folded like a leaf: the "
                        "points across the bone do not curve evenly); 2 moves refused (they would have "
                        "taken a node away from its data)."),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("; 1 extension refused (it would have taken a node away from its data)."), std::string::npos)
        << text;
    EXPECT_TRUE(q.warnings().empty());
    q.nodesAwayFromData = {4, 9};
    const std::vector<QualityWarning> warnings = q.warnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].kind, QualityWarning::Kind::NodesAwayFromData);
    EXPECT_NE(describe(warnings[0].problem).find("2 nodes lie away from their data (first: node 4)"), std::string::npos)
        << describe(warnings[0].problem);
}

TEST(DataSupport, ARibbonLeafGivesACurveAlongItsMidLine) {
    // A leaf blade 1.6 long and 0.3 wide, tapering to both ends, arched along its length and
    // troughed across: its skeleton is its mid-line, two tips, no loop.
    const auto midLine = [](double u) { return Point(1.6 * u, 0, 0.35 * std::sin(M_PI * u)); };
    const shapes::Triangles blade = shapes::sheet(
        [&](double u, double v) {
            const double w = (2 * v - 1) * 0.15 * std::sin(M_PI * (0.04 + 0.92 * u));
            return Point(midLine(u) + Point(0, w, 0.15 * w * w / 0.15));
        },
        48, 8);
    const PointList leaf = shapes::sample(blade, 6000, 11);
    const SkeletonResult result = computeCurveSkeleton(leaf);
    const SkeletonTopology t = analyseTopology(result.skeleton);
    EXPECT_EQ(t.tips, 2) << describe(t);
    EXPECT_EQ(t.cycles, 0) << describe(t);
    shapes::Polyline curve;
    for (int i = 0; i < 64; ++i) curve.push_back({midLine(i / 64.0), midLine((i + 1) / 64.0)});
    const double diagonal = boundingBox(leaf).diagonal().norm();
    double sum = 0;
    for (const Point& node : result.skeleton.nodes) sum += shapes::distanceToCurve(node, curve);
    EXPECT_LT(sum / double(result.skeleton.nodeCount()), 0.015 * diagonal) << "mean distance to the mid-line";
    expectNodesOnTheData(result, leaf, 0.025);
}
