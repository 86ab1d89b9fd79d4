#include "pcskeleton/internal/sparse_spd_solver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <vector>

namespace pcskeleton {

struct SparseSpdSolver::Impl {
    LinearSolver kind;
    Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> cholmod;
    Eigen::SimplicialLDLT<Matrix, Eigen::Lower> simplicial;
    std::vector<int> analysedOuter, analysedInner;

    bool samePattern(const Matrix& m) const {
        return m.nonZeros() == static_cast<Eigen::Index>(analysedInner.size()) &&
               m.outerSize() + 1 == static_cast<Eigen::Index>(analysedOuter.size()) &&
               std::equal(analysedOuter.begin(), analysedOuter.end(), m.outerIndexPtr()) &&
               std::equal(analysedInner.begin(), analysedInner.end(), m.innerIndexPtr());
    }

    void rememberPattern(const Matrix& m) {
        analysedOuter.assign(m.outerIndexPtr(), m.outerIndexPtr() + m.outerSize() + 1);
        analysedInner.assign(m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros());
    }
};

SparseSpdSolver::SparseSpdSolver(LinearSolver kind) : impl_(new Impl) { impl_->kind = kind; }
SparseSpdSolver::~SparseSpdSolver() = default;

bool SparseSpdSolver::factorize(const Matrix& m) {
    const bool analyse = !impl_->samePattern(m);
    if (analyse) impl_->rememberPattern(m);
    if (impl_->kind == LinearSolver::Cholmod) {
        if (analyse) {
            // One ordering instead of CHOLMOD's default trial of several. Measured on
            // sampled surfaces: AMD is as good below ~50K unknowns; above, METIS gives
            // ~20% less fill and saves the time of the AMD trial.
            cholmod_common& settings = impl_->cholmod.cholmod();
            settings.nmethods = 1;
            settings.method[0].ordering = m.rows() > 50000 ? CHOLMOD_METIS : CHOLMOD_AMD;
            impl_->cholmod.analyzePattern(m);
        }
        impl_->cholmod.factorize(m);
        return impl_->cholmod.info() == Eigen::Success;
    }
    if (analyse) impl_->simplicial.analyzePattern(m);
    impl_->simplicial.factorize(m);
    return impl_->simplicial.info() == Eigen::Success;
}

Eigen::MatrixXd SparseSpdSolver::solve(const Eigen::MatrixXd& rhs) const {
    if (impl_->kind == LinearSolver::Cholmod) return impl_->cholmod.solve(rhs);
    return impl_->simplicial.solve(rhs);
}

}  // namespace pcskeleton
