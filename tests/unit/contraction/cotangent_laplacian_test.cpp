// Step 2: the cotangent Laplacian on the 1-rings.
#include <pcskeleton/contraction/cotangent_laplacian.h>
#include <pcskeleton/contraction/one_ring.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pcskeleton;

namespace {

PointList jitteredGrid(int side, double spacing) {
    PointList points;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            points.emplace_back(spacing * (x + 0.3 * std::sin(7.0 * x + 3.0 * y)),
                                spacing * (y + 0.3 * std::cos(5.0 * x - 2.0 * y)), 0.0);
    return points;
}

}  // namespace

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
