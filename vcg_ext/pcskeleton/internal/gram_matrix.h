// The matrix LᵀL of a sparse L whose pattern never changes (the contraction's Laplacian):
// its pattern is worked out once, and each update only recomputes the values in place.
// Eigen's general sparse product would allocate, sort and copy from row to column order
// every iteration, a noticeable share of it (docs/benchmarks.md#measurements-behind-the-constants).
#pragma once

#include <Eigen/SparseCore>

#include <vector>

namespace pcskeleton {

class GramMatrix {
public:
    using Factor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
    using Matrix = Eigen::SparseMatrix<double>;  // column-major, lower triangle only

    // The pattern of the lower triangle of LᵀL for this pattern of L.
    explicit GramMatrix(const Factor& l);

    // Sets the matrix to scale·LᵀL; `l` must have the pattern given at construction.
    void update(const Factor& l, double scale);

    // Lower triangle (the solvers read only that); its pattern is the same after every update.
    Matrix& matrix() { return matrix_; }
    // Position of entry (i, i) in matrix().valuePtr().
    int diagonalSlot(int i) const { return diagonalSlot_[i]; }

private:
    Matrix matrix_;
    // Column j of L: the rows k holding it and where L(k, j) is in L's values.
    std::vector<int> columnStart_, columnRow_, columnSlot_;
    std::vector<int> diagonalSlot_;
};

}  // namespace pcskeleton
