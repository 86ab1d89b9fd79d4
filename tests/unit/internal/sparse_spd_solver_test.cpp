#include <pcskeleton/internal/sparse_spd_solver.h>

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <new>
#include <vector>

using namespace pcskeleton;

namespace {

// The 5-point Laplacian of a side x side grid plus the identity: SPD, and with the fill of
// a surface's system, so CHOLMOD's supernodal factor has dense blocks (BLAS work) and rounds
// otherwise than Eigen's LDLᵀ.
SparseSpdSolver::Matrix gridSystem(int side) {
    std::vector<Eigen::Triplet<double>> entries;
    const auto id = [side](int x, int y) { return x * side + y; };
    for (int x = 0; x < side; ++x) {
        for (int y = 0; y < side; ++y) {
            entries.emplace_back(id(x, y), id(x, y), 5.0 + 0.001 * ((x * 7 + y * 3) % 11));
            if (x + 1 < side) entries.emplace_back(id(x + 1, y), id(x, y), -1.0);
            if (y + 1 < side) entries.emplace_back(id(x, y + 1), id(x, y), -1.0);
        }
    }
    SparseSpdSolver::Matrix m(side * side, side * side);
    m.setFromTriplets(entries.begin(), entries.end());
    return m;  // lower triangle, as the solver reads it
}

Eigen::MatrixXd solveWith(LinearSolver kind, const SparseSpdSolver::Matrix& m) {
    SparseSpdSolver solver(kind);
    EXPECT_TRUE(solver.factorize(m));
    Eigen::MatrixXd rhs(m.rows(), 3);
    for (Eigen::Index i = 0; i < m.rows(); ++i) rhs.row(i) << double(i % 13), 1.0, std::sin(double(i));
    return solver.solve(rhs);
}

}  // namespace

// Up to kLargestPortableSystem unknowns the default takes Eigen's solver, whose result
// does not depend on the CPU's BLAS kernels; above, CHOLMOD's, bit for bit.
TEST(SparseSpdSolver, AutomaticIsEigenUpToThePortableLimitAndCholmodAbove) {
    const SparseSpdSolver::Matrix small = gridSystem(100);  // 10000 unknowns
    ASSERT_LE(small.rows(), kLargestPortableSystem);
    EXPECT_TRUE(solveWith(LinearSolver::Automatic, small) == solveWith(LinearSolver::EigenSimplicial, small));

    const SparseSpdSolver::Matrix large = gridSystem(150);  // 22500 unknowns
    ASSERT_GT(large.rows(), kLargestPortableSystem);
    const Eigen::MatrixXd cholmod = solveWith(LinearSolver::Cholmod, large);
    const Eigen::MatrixXd eigen = solveWith(LinearSolver::EigenSimplicial, large);
    EXPECT_TRUE(solveWith(LinearSolver::Automatic, large) == cholmod);
    // The two solvers agree to rounding, and differ in it (so the checks above can fail).
    EXPECT_LT((cholmod - eigen).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_FALSE(cholmod == eigen);
}

// Running out of memory inside CHOLMOD is std::bad_alloc, never a crash on a missing factor
// nor a "numerical failure". In a child process whose address space is capped just above
// what it maps already (AddressSanitizer reserves terabytes of it: not under ASan).
#if !defined(__SANITIZE_ADDRESS__)
TEST(SparseSpdSolverDeathTest, RunningOutOfMemoryInCholmodIsBadAlloc) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const SparseSpdSolver::Matrix large = gridSystem(400);  // 160000 unknowns: ~100 MB of factor
    const auto outOfMemory = [&] {
        std::ifstream statm("/proc/self/statm");
        double pages = 0;
        statm >> pages;
        const rlim_t mapped = rlim_t(pages * double(sysconf(_SC_PAGE_SIZE)));
        const rlimit cap{mapped + (16u << 20), mapped + (16u << 20)};
        setrlimit(RLIMIT_AS, &cap);
        try {
            SparseSpdSolver solver(LinearSolver::Cholmod);
            solver.factorize(large);
            solver.solve(Eigen::MatrixXd::Ones(large.rows(), 3));
        } catch (const std::bad_alloc&) {
            std::_Exit(42);
        }
        std::_Exit(0);
    };
    EXPECT_EXIT(outOfMemory(), ::testing::ExitedWithCode(42), "");
}
#endif
