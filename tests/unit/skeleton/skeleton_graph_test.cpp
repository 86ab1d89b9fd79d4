// The skeleton graph's topology numbers on a graph whose answer is known.
#include <pcskeleton/skeleton/skeleton_graph.h>

#include <gtest/gtest.h>

using namespace pcskeleton;

TEST(Topology, CountsCyclesTipsAndJunctions) {
    // A triangle-free "theta" graph plus an isolated node and a path.
    const std::vector<Edge> edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {4, 2}, {6, 7}};
    const SkeletonTopology t = analyseTopology(8, edges);
    EXPECT_EQ(t.components, 3);
    EXPECT_EQ(t.cycles, 2);
    EXPECT_EQ(t.junctions, 2);
    EXPECT_EQ(t.tips, 2);
    EXPECT_EQ(t.isolated, 1);
}
