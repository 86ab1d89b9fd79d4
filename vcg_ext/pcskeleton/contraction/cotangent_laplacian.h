// Step 2 of the paper (Sec. III-A): the point-cloud Laplacian with cotangent weights.
//
// Row i holds, for every 1-ring neighbour j, the sum of the cotangents of the angles
// opposite the edge (i, j) in i's fan, evaluated on the *current* positions; the diagonal
// makes each row sum to zero. The sparsity pattern comes from the fixed 1-rings, so it
// is built once and only the values change from one iteration to the next.
#pragma once

#include "pcskeleton/contraction/one_ring.h"

#include <Eigen/SparseCore>

#include <vector>

namespace pcskeleton {

class CotangentLaplacian {
public:
    using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

    // rowWeightLimit: a row whose absolute off-diagonal weights add up to more than this
    // is scaled down to it. Nearly flat fan triangles (they appear as points collapse)
    // have huge cotangents; the limit keeps the system well conditioned.
    CotangentLaplacian(const OneRings& rings, double rowWeightLimit);

    // Recomputes the weights on `positions`; the pattern is unchanged.
    void update(const PointList& positions);

    const Matrix& matrix() const { return matrix_; }

private:
    const OneRings& rings_;
    double rowWeightLimit_;
    Matrix matrix_;
    // For fan triangle t of row i, where the weights of edges (i, a) and (i, b) are stored.
    std::vector<std::array<int, 2>> edgeSlots_;
    std::vector<int> diagonalSlot_;
};

// cot of the angle at `apex` in the triangle (apex, p, q); 0 when it is undefined
// (a zero-length side), large but finite when the triangle is flat.
double cotangentAt(const Point& apex, const Point& p, const Point& q);

}  // namespace pcskeleton
