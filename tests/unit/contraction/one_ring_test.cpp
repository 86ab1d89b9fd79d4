// Step 1: the tangent-plane Delaunay 1-rings, on inputs with known structure.
#include <pcskeleton/contraction/one_ring.h>
#include "support/sampled_shapes.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace pcskeleton;

namespace {

bool inRing(const OneRings& rings, int i, int j) {
    return std::binary_search(rings.ringBegin(i), rings.ringEnd(i), j);
}

}  // namespace

TEST(OneRing, PapersNeighbourCountIs1Point2PercentOfThePointsWithin8And30) {
    EXPECT_EQ(paperNeighbourCount(100), 8);
    EXPECT_EQ(paperNeighbourCount(1000), 12);
    EXPECT_EQ(paperNeighbourCount(2000), 24);
    EXPECT_EQ(paperNeighbourCount(100000), 30);
}

TEST(OneRing, DefaultNeighbourCountIsThePapersButAtLeastA30thOfThePointsUpTo20) {
    EXPECT_EQ(defaultNeighbourCount(20), 8) << "a tiny cloud keeps the paper's least";
    EXPECT_EQ(defaultNeighbourCount(231), 8);
    EXPECT_EQ(defaultNeighbourCount(300), 10) << "a 30th of the points";
    EXPECT_EQ(defaultNeighbourCount(500), 16) << "a 30th of the points";
    EXPECT_EQ(defaultNeighbourCount(600), kFewestDefaultNeighbours);
    EXPECT_EQ(defaultNeighbourCount(1000), kFewestDefaultNeighbours);
    EXPECT_EQ(defaultNeighbourCount(2000), 24) << "the paper's rule where it gives more";
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

// With every other point as a neighbour, a flat cloud's local triangulations are pieces of
// one: each point's fan is its star in the Delaunay triangulation of the whole cloud.
TEST(OneRing, EachFanIsThePointsStarInTheDelaunayTriangulationOfAFlatCloud) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
    using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<VertexBase>>;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    PointList points;
    std::vector<std::pair<Kernel::Point_2, int>> planar;
    for (int i = 0; i < 300; ++i) {
        const double x = coordinate(random), y = coordinate(random);
        points.emplace_back(x, y, 0.0);
        planar.emplace_back(Kernel::Point_2(x, y), i);
    }
    const Delaunay delaunay(planar.begin(), planar.end());
    const OneRings rings = OneRings::compute(points, int(points.size()) - 1);

    using Triangle = std::pair<int, int>;  // the two other corners, smaller first
    auto unordered = [](int a, int b) { return Triangle(std::min(a, b), std::max(a, b)); };
    for (Delaunay::Vertex_handle v : delaunay.finite_vertex_handles()) {
        const int i = v->info();
        std::set<Triangle> expected, found;
        Delaunay::Face_circulator face = delaunay.incident_faces(v), end = face;
        do {
            if (delaunay.is_infinite(face)) continue;
            const int c = face->index(v);
            expected.insert(unordered(face->vertex(Delaunay::ccw(c))->info(), face->vertex(Delaunay::cw(c))->info()));
        } while (++face != end);
        for (auto t = rings.fanBegin(i); t != rings.fanEnd(i); ++t) found.insert(unordered((*t)[0], (*t)[1]));
        EXPECT_EQ(found, expected) << "point " << i;
    }
}
