// Step 1 (1-rings) and step 2 (cotangent Laplacian) on inputs with known structure.
#include <pcskeleton/cotangent_laplacian.h>
#include <pcskeleton/one_ring.h>
#include <pcskeleton/sampled_shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace pcskeleton;

namespace {

bool inRing(const OneRings& rings, int i, int j) {
    return std::binary_search(rings.ringBegin(i), rings.ringEnd(i), j);
}

PointList jitteredGrid(int side, double spacing) {
    PointList points;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            points.emplace_back(spacing * (x + 0.3 * std::sin(7.0 * x + 3.0 * y)),
                                spacing * (y + 0.3 * std::cos(5.0 * x - 2.0 * y)), 0.0);
    return points;
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

TEST(Laplacian, RowsSumToZero) {
    const PointList points = shapes::torus(2000, 1.0, 0.3);
    const OneRings rings = OneRings::compute(points, 16);
    CotangentLaplacian laplacian(rings, 1e4);
    laplacian.update(points);
    const auto& L = laplacian.matrix();
    for (int i = 0; i < L.rows(); ++i) EXPECT_NEAR(L.row(i).sum(), 0.0, 1e-9);
}

TEST(Laplacian, ReproducesLinearFunctionsInsideAPlane) {
    // Cotangent weights have linear precision: L P = 0 at interior points of a flat patch.
    const int side = 30;
    const PointList points = jitteredGrid(side, 0.1);
    const OneRings rings = OneRings::compute(points, 12);
    CotangentLaplacian laplacian(rings, 1e4);
    laplacian.update(points);
    Eigen::MatrixXd P(points.size(), 3);
    for (std::size_t i = 0; i < points.size(); ++i) P.row(i) = points[i].transpose();
    const Eigen::MatrixXd LP = laplacian.matrix() * P;
    int interior = 0;
    for (int y = 3; y < side - 3; ++y)
        for (int x = 3; x < side - 3; ++x, ++interior) EXPECT_LT(LP.row(y * side + x).norm(), 1e-9);
    EXPECT_GT(interior, 500);
}

TEST(Laplacian, DegenerateTrianglesGiveFiniteBoundedWeights) {
    EXPECT_EQ(cotangentAt(Point(0, 0, 0), Point(0, 0, 0), Point(1, 0, 0)), 0.0);
    const double flat = cotangentAt(Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0));
    EXPECT_TRUE(std::isfinite(flat));
    EXPECT_NEAR(cotangentAt(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)), 0.0, 1e-12);
    EXPECT_NEAR(cotangentAt(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0)), 1.0, 1e-12);

    // Collapse a cloud onto a line: every weight stays finite and rows obey the limit.
    const PointList points = shapes::cylinder(1500, 0.1, 1.0, false);
    const OneRings rings = OneRings::compute(points, 12);
    PointList collapsed = points;
    for (Point& p : collapsed) p.x() = p.y() = 0;
    CotangentLaplacian laplacian(rings, 1e4);
    laplacian.update(collapsed);
    const auto& L = laplacian.matrix();
    for (int i = 0; i < L.rows(); ++i) {
        double offDiagonal = 0;
        for (CotangentLaplacian::Matrix::InnerIterator it(L, i); it; ++it) {
            ASSERT_TRUE(std::isfinite(it.value()));
            if (it.col() != i) offDiagonal += std::abs(it.value());
        }
        EXPECT_LE(offDiagonal, 1e4 * (1 + 1e-12));
    }
}
