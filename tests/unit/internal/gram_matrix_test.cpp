#include <pcskeleton/contraction/cotangent_laplacian.h>
#include <pcskeleton/core/errors.h>
#include <pcskeleton/internal/gram_matrix.h>
#include "support/sampled_shapes.h"

#include <gtest/gtest.h>

#include <random>

using namespace pcskeleton;

namespace {

// The lower triangle of LᵀL by Eigen's general product, the reference.
Eigen::MatrixXd referenceLower(const GramMatrix::Factor& l, double scale) {
    const Eigen::MatrixXd dense = scale * Eigen::MatrixXd(l).transpose() * Eigen::MatrixXd(l);
    return dense.triangularView<Eigen::Lower>();
}

// A random row-major L with a diagonal in every row and a few off-diagonal entries.
GramMatrix::Factor randomFactor(int n, std::mt19937& random) {
    std::uniform_int_distribution<int> column(0, n - 1);
    std::uniform_real_distribution<double> value(-2.0, 2.0);
    std::vector<Eigen::Triplet<double>> entries;
    for (int k = 0; k < n; ++k) {
        entries.emplace_back(k, k, value(random) + 5.0);
        for (int e = 0; e < 4; ++e) entries.emplace_back(k, column(random), value(random));
    }
    GramMatrix::Factor l(n, n);
    l.setFromTriplets(entries.begin(), entries.end());
    return l;
}

}  // namespace

TEST(GramMatrix, EqualsTheProductOfLTransposedAndL) {
    std::mt19937 random(7);
    GramMatrix::Factor l = randomFactor(60, random);
    GramMatrix gram(l);
    gram.update(l, 3.0);
    EXPECT_LT((Eigen::MatrixXd(gram.matrix()) - referenceLower(l, 3.0)).cwiseAbs().maxCoeff(), 1e-12);
    for (int i = 0; i < 60; ++i) {
        EXPECT_EQ(gram.matrix().innerIndexPtr()[gram.diagonalSlot(i)], i);
    }
}

TEST(GramMatrix, NewValuesInTheSamePatternGiveTheNewProductWithoutReallocating) {
    std::mt19937 random(8);
    GramMatrix::Factor l = randomFactor(40, random);
    GramMatrix gram(l);
    gram.update(l, 1.0);
    const double* storage = gram.matrix().valuePtr();
    const Eigen::Index nonZeros = gram.matrix().nonZeros();
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (Eigen::Index s = 0; s < l.nonZeros(); ++s) l.valuePtr()[s] = value(random);
    gram.update(l, 0.5);
    EXPECT_EQ(gram.matrix().valuePtr(), storage);
    EXPECT_EQ(gram.matrix().nonZeros(), nonZeros);
    EXPECT_LT((Eigen::MatrixXd(gram.matrix()) - referenceLower(l, 0.5)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(GramMatrix, OfTheContractionLaplacianOfATorus) {
    const PointList points = shapes::torus(1500, 1.0, 0.3);
    const OneRings rings = OneRings::compute(points, 10);
    CotangentLaplacian laplacian(rings, 1e4);
    laplacian.update(points);
    GramMatrix gram(laplacian.matrix());
    gram.update(laplacian.matrix(), 2.0);
    const Eigen::SparseMatrix<double> reference = (2.0 * laplacian.matrix().transpose() * laplacian.matrix()).eval();
    const Eigen::SparseMatrix<double> lower = reference.triangularView<Eigen::Lower>();
    EXPECT_LT((Eigen::MatrixXd(gram.matrix()) - Eigen::MatrixXd(lower)).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(GramMatrix, RefusesAFactorWithoutItsDiagonal) {
    GramMatrix::Factor l(2, 2);
    l.insert(0, 1) = 1.0;
    l.insert(1, 1) = 1.0;
    EXPECT_THROW(GramMatrix{l}, CallerError);
}
