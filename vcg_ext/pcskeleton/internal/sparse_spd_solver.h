// A sparse symmetric positive definite solver whose pattern is analysed once and then
// refactorised numerically, as the contraction needs on every iteration.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace pcskeleton {

enum class LinearSolver {
    Cholmod,          // SuiteSparse CHOLMOD supernodal Cholesky (the default: fastest measured)
    EigenSimplicial,  // Eigen's SimplicialLDLT (no SuiteSparse needed; kept for comparison)
};

class SparseSpdSolver {
public:
    using Matrix = Eigen::SparseMatrix<double>;

    explicit SparseSpdSolver(LinearSolver kind);
    ~SparseSpdSolver();
    SparseSpdSolver(const SparseSpdSolver&) = delete;
    SparseSpdSolver& operator=(const SparseSpdSolver&) = delete;

    // Factorises `m`, re-analysing its pattern only when it differs from the last one.
    // Returns false when the matrix is not numerically positive definite.
    bool factorize(const Matrix& m);
    Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace pcskeleton
