#include "pcskeleton/internal/sparse_spd_solver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include <dlfcn.h>

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace pcskeleton {

namespace {

// CHOLMOD's supernodal factorisation calls BLAS, and OpenBLAS divides that work by its
// thread count with a different rounding for each: 1 and 2 threads gave different
// skeleton files. One BLAS thread during our factorisations keeps results byte-identical
// from run to run on one machine (the contraction's 10K-100K-point systems have small
// supernodes, where BLAS threads gain little); across CPUs OpenBLAS's kernels differ
// (sparse_spd_solver.h). OpenBLAS is reached through the loaded BLAS library (it may
// be local to a plugin); any other BLAS is left alone.
class OneBlasThread {
public:
    OneBlasThread() {
        for (const char* library : {"libblas.so.3", "libopenblas.so.0"}) {
            void* handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD);
            if (!handle) continue;
            get_ = reinterpret_cast<int (*)()>(dlsym(handle, "openblas_get_num_threads"));
            set_ = reinterpret_cast<void (*)(int)>(dlsym(handle, "openblas_set_num_threads"));
            dlclose(handle);  // still loaded: NOLOAD only counted a reference
            if (get_ && set_) break;
        }
        if (get_ && set_) {
            previous_ = get_();
            set_(1);
        }
    }
    ~OneBlasThread() {
        if (get_ && set_) set_(previous_);
    }
    OneBlasThread(const OneBlasThread&) = delete;
    OneBlasThread& operator=(const OneBlasThread&) = delete;

private:
    int (*get_)() = nullptr;
    void (*set_)(int) = nullptr;
    int previous_ = 1;
};

// CHOLMOD keeps its status in its settings: out of memory (or beyond the size of its
// integers) as std::bad_alloc, as Eigen's own solver reports it; anything else is a bug.
void throwIfCholmodFailed(const cholmod_common& settings) {
    if (settings.status >= CHOLMOD_OK || settings.status == CHOLMOD_NOT_POSDEF) return;
    if (settings.status == CHOLMOD_OUT_OF_MEMORY || settings.status == CHOLMOD_TOO_LARGE) throw std::bad_alloc();
    throw std::logic_error("CHOLMOD failed with status " + std::to_string(settings.status));
}

}  // namespace

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

    void forgetPattern() { analysedOuter.clear(), analysedInner.clear(); }

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
    if (impl_->kind == LinearSolver::Automatic) {
        impl_->kind = m.rows() <= kLargestPortableSystem ? LinearSolver::EigenSimplicial : LinearSolver::Cholmod;
    }
    if (impl_->kind == LinearSolver::Cholmod) {
        const OneBlasThread deterministic;
        if (analyse) {
            // One ordering instead of CHOLMOD's default trial of several: AMD is as good
            // on small systems, METIS gives less fill on large ones
            // (docs/benchmarks.md#measurements-behind-the-constants).
            cholmod_common& settings = impl_->cholmod.cholmod();
            settings.nmethods = 1;
            settings.method[0].ordering = m.rows() > 50000 ? CHOLMOD_METIS : CHOLMOD_AMD;
            impl_->cholmod.analyzePattern(m);
            // Eigen reports success even when CHOLMOD could not analyse (out of memory) and
            // would then factorise with a null factor: forget the pattern, so that a later
            // call analyses it again, and refuse.
            if (settings.status < CHOLMOD_OK) impl_->forgetPattern();
            throwIfCholmodFailed(settings);
        }
        impl_->cholmod.factorize(m);
        // Running out of memory half-way leaves a partial factor that Eigen reports as a
        // numerical failure: it is not one.
        throwIfCholmodFailed(impl_->cholmod.cholmod());
        return impl_->cholmod.info() == Eigen::Success;
    }
    if (analyse) impl_->simplicial.analyzePattern(m);
    impl_->simplicial.factorize(m);
    return impl_->simplicial.info() == Eigen::Success;
}

Eigen::MatrixXd SparseSpdSolver::solve(const Eigen::MatrixXd& rhs) const {
    if (impl_->kind == LinearSolver::Cholmod) {
        const OneBlasThread deterministic;
        Eigen::MatrixXd x = impl_->cholmod.solve(rhs);
        throwIfCholmodFailed(impl_->cholmod.cholmod());
        if (impl_->cholmod.info() != Eigen::Success) throw std::logic_error("SparseSpdSolver: solving without a factor");
        return x;
    }
    if (impl_->simplicial.info() != Eigen::Success) throw std::logic_error("SparseSpdSolver: solving without a factor");
    return impl_->simplicial.solve(rhs);
}

}  // namespace pcskeleton
