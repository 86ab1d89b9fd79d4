// Step 5: nodes at the centre of their points, in the input's frame; radii their mean
// distance; one correspondence entry per input point (outliers -1, duplicates with their
// twin); a node with a single point takes its neighbours' radius.
#include <pcskeleton/skeleton/skeleton_embedding.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace pcskeleton;

namespace {

// Points on a circle of radius r around `centre`, in the plane z = centre.z.
void addCircle(PointList& points, const Point& centre, double r, int count) {
    for (int i = 0; i < count; ++i) {
        const double a = 2 * M_PI * i / count;
        points.push_back(centre + Point(r * std::cos(a), r * std::sin(a), 0));
    }
}

}  // namespace

TEST(SkeletonEmbedding, NodesAtTheCentreOfTheirPointsWithTheirMeanDistanceAsRadius) {
    NormalizedCloud cloud;
    cloud.center = Point(10, 20, 30);
    cloud.scale = 4.0;  // normalised = (input - center) * 4
    addCircle(cloud.points, Point(0, 0, 0), 0.2, 8);
    addCircle(cloud.points, Point(0, 0, 1), 0.1, 6);
    cloud.points.push_back(Point(0, 0, 1.5));  // a node of its own, one point
    // Input: every unique point once, then a duplicate of point 3 and an outlier.
    for (int i = 0; i < int(cloud.points.size()); ++i) cloud.uniqueIndex.push_back(i);
    cloud.uniqueIndex.push_back(3);
    cloud.uniqueIndex.push_back(-1);
    cloud.outliers.push_back(Point(99, 99, 99));

    ThinnedGraph graph;
    graph.nodes = {Point(0.05, 0, 0), Point(0, 0.02, 1), Point(0, 0, 1.5)};  // off-centre, as contracted
    graph.edges = {{0, 1}, {1, 2}};
    graph.owner.assign(8, 0);
    graph.owner.insert(graph.owner.end(), 6, 1);
    graph.owner.push_back(2);

    const SkeletonGraph s = embedSkeleton(graph, cloud);
    ASSERT_EQ(s.nodes.size(), 3u);
    EXPECT_LT((s.nodes[0] - cloud.toInputFrame(Point(0, 0, 0))).norm(), 1e-12);
    EXPECT_LT((s.nodes[1] - cloud.toInputFrame(Point(0, 0, 1))).norm(), 1e-12);
    EXPECT_LT((s.nodes[2] - cloud.toInputFrame(Point(0, 0, 1.5))).norm(), 1e-12);
    EXPECT_NEAR(s.radii[0], 0.2 / 4.0, 1e-12);  // input units
    EXPECT_NEAR(s.radii[1], 0.1 / 4.0, 1e-12);
    EXPECT_GT(s.radii[2], 0.0);                  // filled from its neighbour
    EXPECT_EQ(s.edges, graph.edges);

    ASSERT_EQ(s.pointNode.size(), cloud.inputSize());
    for (int i = 0; i < 8; ++i) EXPECT_EQ(s.pointNode[i], 0);
    for (int i = 8; i < 14; ++i) EXPECT_EQ(s.pointNode[i], 1);
    EXPECT_EQ(s.pointNode[14], 2);
    EXPECT_EQ(s.pointNode[15], s.pointNode[3]);  // the duplicate follows its twin
    EXPECT_EQ(s.pointNode[16], -1);              // the outlier has no node
}
