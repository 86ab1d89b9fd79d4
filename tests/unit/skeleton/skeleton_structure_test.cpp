// Limbs, spurs and spurious loops on hand-made graphs whose flaws are known.
#include <pcskeleton/skeleton/skeleton_structure.h>
#include "support/hand_made_graphs.h"
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

using namespace pcskeleton;
using namespace pcskeleton::graphs;

TEST(SkeletonStructure, AShortLimbInsideTheBodyIsASpurALongOneIsNot) {
    SkeletonGraph g = straightChain();
    const int spurTip = addNode(g, Point(0.5, 0.1, 0), 5);  // 0.1 long, the body is 0.2 thick
    int limbTip = 7;
    for (int step = 1; step <= 5; ++step) limbTip = addNode(g, Point(0.7, 0.1 * step, 0), limbTip);
    int spurs = 0, limbs = 0;
    for (const Limb& limb : tipLimbs(g)) {
        if (limb.path.front() == spurTip) {
            EXPECT_TRUE(isSpur(g, limb, kSpacing));
            ++spurs;
        }
        if (limb.path.front() == limbTip) {
            EXPECT_FALSE(isSpur(g, limb, kSpacing));
            ++limbs;
        }
        if (limb.path.front() == 0 || limb.path.front() == 10) EXPECT_FALSE(isSpur(g, limb, kSpacing));
    }
    EXPECT_EQ(spurs, 1);
    EXPECT_EQ(limbs, 1);
}

TEST(SkeletonStructure, ALoopWithoutAHoleIsSpuriousARingIsNot) {
    SkeletonGraph g = straightChain();
    // A square loop of side 0.05 hanging on node 5: the 0.2 tube around it fills it.
    const int a = addNode(g, Point(0.5, 0.05, 0), 5);
    const int b = addNode(g, Point(0.55, 0.05, 0), a);
    const int c = addNode(g, Point(0.55, 0.0, 0.02), b);
    g.edges.push_back({5, c});
    normalizeEdges(g.edges);
    const auto cycles = shortCycleBasis(g);
    ASSERT_EQ(cycles.size(), 1u);
    EXPECT_EQ(cycles[0].size(), 4u);
    EXPECT_TRUE(isSpuriousCycle(g, cycles[0], kSpacing));

    const SkeletonGraph ring = shapes::curveSkeleton(shapes::circle(Point::Zero(), 1.0, 24), 0.3);
    const auto ringCycles = shortCycleBasis(ring);
    ASSERT_EQ(ringCycles.size(), 1u);
    EXPECT_EQ(ringCycles[0].size(), 24u);
    EXPECT_FALSE(isSpuriousCycle(ring, ringCycles[0], kSpacing));
}
