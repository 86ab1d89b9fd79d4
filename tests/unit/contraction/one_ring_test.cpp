// Step 1: the tangent-plane Delaunay 1-rings, on inputs with known structure.
#include <pcskeleton/contraction/one_ring.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace pcskeleton;

namespace {

bool inRing(const OneRings& rings, int i, int j) {
    return std::binary_search(rings.ringBegin(i), rings.ringEnd(i), j);
}

}  // namespace

TEST(OneRing, NeighbourCountFollowsThePapersRule) {
    EXPECT_EQ(defaultNeighbourCount(100), 8);
    EXPECT_EQ(defaultNeighbourCount(1000), 12);
    EXPECT_EQ(defaultNeighbourCount(2000), 24);
    EXPECT_EQ(defaultNeighbourCount(100000), 30);
}

TEST(OneRing, RingsOfASmoothSurfaceLookLikeATriangulation) {
    const PointList points = shapes::sphere(3000, 1.0);
    const OneRings rings = OneRings::compute(points, 20);
    ASSERT_EQ(rings.size(), points.size());
    std::size_t entries = 0, symmetric = 0;
    for (std::size_t i = 0; i < rings.size(); ++i) {
        // Closed fans on a closed surface: about 6 neighbours (Euler), never fewer than 3.
        EXPECT_GE(rings.ringSize(i), 3u);
        EXPECT_EQ(std::size_t(rings.fanEnd(i) - rings.fanBegin(i)), rings.ringSize(i)) << "open fan at " << i;
        for (const int* j = rings.ringBegin(i); j != rings.ringEnd(i); ++j) {
            EXPECT_NE(*j, int(i));
            ++entries;
            symmetric += inRing(rings, *j, int(i));
        }
    }
    const double meanValence = double(entries) / rings.size();
    EXPECT_NEAR(meanValence, 6.0, 0.2);
    // Local triangulations mostly agree with each other: the Laplacian is nearly symmetric.
    EXPECT_GT(double(symmetric) / entries, 0.95);
}

TEST(OneRing, FanTrianglesAreMadeOfRingNeighbours) {
    const OneRings rings = OneRings::compute(shapes::torus(3000, 1.0, 0.3), 16);
    for (std::size_t i = 0; i < rings.size(); ++i) {
        for (auto t = rings.fanBegin(i); t != rings.fanEnd(i); ++t) {
            EXPECT_TRUE(inRing(rings, int(i), (*t)[0]));
            EXPECT_TRUE(inRing(rings, int(i), (*t)[1]));
            EXPECT_NE((*t)[0], (*t)[1]);
        }
    }
}
