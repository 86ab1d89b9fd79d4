// The Section V field solver on small grids, where the assembled system can be solved
// directly and compared with the matrix-free multigrid solution.
#include <pcskeleton/reconstruction/field_fitting.h>

#include <pcskeleton/internal/sparse_spd_solver.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pcskeleton {
namespace {

// A sphere of radius 0.3 in the unit box: surface samples at 0, its centre at -0.3, the
// box's boundary held at the distance to the sphere.
FieldProblem sphereProblem(std::array<int, 3> nodes) {
    FieldProblem problem;
    problem.grid.nodes = nodes;
    problem.grid.spacing = 1.0 / (nodes[0] - 1);
    const Point centre(0.5, 0.5, 0.5 * (nodes[2] - 1) * problem.grid.spacing);
    std::mt19937 rng(3);
    std::normal_distribution<double> gauss;
    for (int s = 0; s < 400; ++s) {
        const Point direction = Point(gauss(rng), gauss(rng), gauss(rng)).normalized();
        problem.pointConstraints.push_back({centre + 0.3 * direction, 0.0, 5.0});
    }
    problem.pointConstraints.push_back({centre, -0.3, 0.5});
    problem.nodeWeight.assign(problem.grid.size(), 0.0);
    problem.nodeValue.assign(problem.grid.size(), 0.0);
    for (int k = 0; k < nodes[2]; ++k)
        for (int j = 0; j < nodes[1]; ++j)
            for (int i = 0; i < nodes[0]; ++i)
                if (problem.grid.isBoundary(i, j, k)) {
                    const std::size_t n = problem.grid.index(i, j, k);
                    problem.nodeWeight[n] = 36.0 / problem.grid.spacing;
                    problem.nodeValue[n] = (problem.grid.position(i, j, k) - centre).norm() - 0.3;
                }
    return problem;
}

TEST(FieldFitting, MatrixFreeOperatorEqualsTheAssembledMatrix) {
    const FieldProblem problem = sphereProblem({9, 9, 7});
    const Eigen::SparseMatrix<double> a = assembleFieldMatrix(problem);
    EXPECT_EQ(a.rows(), 9 * 9 * 7);
    EXPECT_TRUE(a.isApprox(a.transpose()));
    Eigen::VectorXd u = Eigen::VectorXd::Random(a.rows());
    EXPECT_LT((applyFieldMatrix(problem, u) - a * u).norm(), 1e-10 * (a * u).norm());
}

TEST(FieldFitting, SmoothnessTermIsTheSquaredLaplacian) {
    // A quadratic u = x² has Laplacian 2 everywhere: uᵀAu = w Σ_interior h³ 2² with no constraint.
    FieldProblem problem;
    problem.grid.nodes = {7, 6, 5};
    problem.grid.spacing = 0.1;
    problem.smoothnessWeight = 3.0;
    Eigen::VectorXd u(problem.grid.size());
    for (int k = 0; k < 5; ++k)
        for (int j = 0; j < 6; ++j)
            for (int i = 0; i < 7; ++i) u[problem.grid.index(i, j, k)] = std::pow(problem.grid.position(i, j, k).x(), 2);
    const double interiorNodes = 5 * 4 * 3;
    EXPECT_NEAR(u.dot(applyFieldMatrix(problem, u)), 3.0 * interiorNodes * std::pow(0.1, 3) * 4.0, 1e-9);
}

TEST(FieldFitting, MultigridSolutionMatchesTheDirectSolve) {
    const FieldProblem problem = sphereProblem({33, 33, 25});
    const Eigen::SparseMatrix<double> a = assembleFieldMatrix(problem);
    SparseSpdSolver cholesky(LinearSolver::Cholmod);
    ASSERT_TRUE(cholesky.factorize(a));
    const Eigen::VectorXd direct = cholesky.solve(fieldRightHandSide(problem));

    FieldSolveReport report;
    const std::vector<double> solved = solveField(problem, {}, FieldSolverOptions{1e-10, 200}, report);
    EXPECT_TRUE(report.converged);
    EXPECT_GE(report.levels, 3);
    EXPECT_LT(report.iterations, 30);
    const Eigen::Map<const Eigen::VectorXd> multigrid(solved.data(), solved.size());
    EXPECT_LT((multigrid - direct).cwiseAbs().maxCoeff(), 1e-7);
    // And the field is what the constraints say: negative at the centre, about 0 on the sphere.
    EXPECT_LT(direct[problem.grid.index(16, 16, 12)], -0.05);
}

TEST(FieldFitting, InterpolationToAFinerGridIsExactForTrilinearFields) {
    FieldGrid fine;
    fine.nodes = {9, 5, 7};
    fine.spacing = 0.25;
    const FieldGrid coarse = fine.coarser();
    auto f = [](const Point& p) { return 1 + 2 * p.x() - p.y() + 0.5 * p.z() + p.x() * p.y() * p.z(); };
    std::vector<double> values(coarse.size());
    for (int k = 0; k < coarse.nodes[2]; ++k)
        for (int j = 0; j < coarse.nodes[1]; ++j)
            for (int i = 0; i < coarse.nodes[0]; ++i) values[coarse.index(i, j, k)] = f(coarse.position(i, j, k));
    const std::vector<double> interpolated = interpolateToFiner(coarse, fine, values);
    for (int k = 0; k < fine.nodes[2]; ++k)
        for (int j = 0; j < fine.nodes[1]; ++j)
            for (int i = 0; i < fine.nodes[0]; ++i)
                EXPECT_NEAR(interpolated[fine.index(i, j, k)], f(fine.position(i, j, k)), 1e-12);
}

TEST(FieldFitting, RefusesAProblemWithoutConstraints) {
    FieldProblem problem;
    problem.grid.nodes = {9, 9, 9};
    problem.grid.spacing = 0.125;
    FieldSolveReport report;
    EXPECT_THROW(solveField(problem, {}, {}, report), InvalidInput);
}

}  // namespace
}  // namespace pcskeleton
