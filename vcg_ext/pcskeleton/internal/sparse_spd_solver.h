// A sparse symmetric positive definite solver whose pattern is analysed once and then
// refactorised numerically, as the contraction needs on every iteration.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace pcskeleton {

enum class LinearSolver {
    // The default: EigenSimplicial up to kLargestPortableSystem unknowns, Cholmod above.
    Automatic,
    // SuiteSparse CHOLMOD supernodal Cholesky: the fastest on large systems. Its dense
    // blocks go to the machine's BLAS, and OpenBLAS picks its kernels by CPU, so the same
    // cloud can give different skeletons on different CPUs.
    Cholmod,
    // Eigen's SimplicialLDLT: our own compiled code only, no BLAS, so the result does not
    // depend on the CPU's BLAS kernels; close to CHOLMOD's speed up to the limit
    // (docs/benchmarks.md#measurements-behind-the-constants).
    EigenSimplicial,
};

// Every contraction at the default settings is at most this large (15000 contracted
// points), so its result does not depend on the CPU's BLAS kernels.
inline constexpr long kLargestPortableSystem = 20000;

class SparseSpdSolver {
public:
    using Matrix = Eigen::SparseMatrix<double>;

    explicit SparseSpdSolver(LinearSolver kind);
    ~SparseSpdSolver();
    SparseSpdSolver(const SparseSpdSolver&) = delete;
    SparseSpdSolver& operator=(const SparseSpdSolver&) = delete;

    // Factorises `m`, re-analysing its pattern only when it differs from the last one.
    // Returns false when the matrix is not numerically positive definite; throws
    // std::bad_alloc when memory runs out (CHOLMOD's status included).
    bool factorize(const Matrix& m);
    Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace pcskeleton
