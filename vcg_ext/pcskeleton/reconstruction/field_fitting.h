// Section V, equation (3): the scalar field u on a grid minimising
//
//     w_smooth ∫ (Δu)²  +  Σ_points w (u(p) − k)²  +  Σ_nodes w (u(node) − k)²
//
// where u(p) is trilinear interpolation (surface and skeleton samples) and the node terms
// are the "outside" constraints. ∫(Δu)² is discretised with the 7-point Laplacian at the
// interior nodes (no boundary condition is imposed: the natural one of the energy).
//
// The minimiser solves a sparse SPD system with a 25-point stencil whose condition number
// grows like (grid size)⁴, so plain or Jacobi-preconditioned CG needs thousands of
// iterations at 128³. It is solved matrix-free by conjugate gradients preconditioned with
// one geometric multigrid V-cycle (Chebyshev-Jacobi smoothing, trilinear transfer,
// re-discretised coarse levels, a direct Cholesky solve on the coarsest): the number of
// iterations stays nearly flat as the grid is refined.
#pragma once

#include "pcskeleton/reconstruction/field_grid.h"
#include "pcskeleton/core/progress.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace pcskeleton {

struct PointConstraint {
    Point position;  // grid frame
    double value;    // k(p)
    double weight;   // w
};

struct FieldProblem {
    FieldGrid grid;
    double smoothnessWeight = 1.0;                  // w_smooth
    std::vector<PointConstraint> pointConstraints;  // read through trilinear interpolation
    std::vector<double> nodeWeight;                 // per node, 0 = unconstrained (or empty: none)
    std::vector<double> nodeValue;                  // per node, the target where nodeWeight > 0
};

struct FieldSolverOptions {
    // On the residual relative to the right-hand side: tighter tolerances give the same
    // surfaces for more iterations (docs/benchmarks.md#measurements-behind-the-constants).
    double tolerance = 3e-5;
    int maxIterations = 100;
};

struct FieldSolveReport {
    int levels = 0;             // multigrid levels, the finest included
    int iterations = 0;         // conjugate-gradient iterations
    double relativeResidual = 0;
    bool converged = false;
};

// Minimises the energy, starting from `initialGuess` (one value per node, or empty for 0).
// Throws InvalidInput when the problem is malformed or not positive definite (no
// constraint at all).
std::vector<double> solveField(const FieldProblem& problem, const std::vector<double>& initialGuess,
                               const FieldSolverOptions& options, FieldSolveReport& report,
                               const ProgressCallback& progress = {});

// Trilinear interpolation of node values from `coarse` to `fine` (fine = coarse.coarser()'s
// source grid): how the multigrid moves corrections up, and how values computed on a
// coarse grid are spread to a fine one.
std::vector<double> interpolateToFiner(const FieldGrid& coarse, const FieldGrid& fine, const std::vector<double>& values);

// The normal equations A u = b of the energy (A = w_smooth S + Σ w s sᵀ + diag(node
// weights), s a point's trilinear weights), assembled: for small grids and tests, the
// solver itself never assembles the finest level.
Eigen::SparseMatrix<double> assembleFieldMatrix(const FieldProblem& problem);
Eigen::VectorXd fieldRightHandSide(const FieldProblem& problem);
// A·u computed the way the solver does, without assembling A.
Eigen::VectorXd applyFieldMatrix(const FieldProblem& problem, const Eigen::VectorXd& u);

}  // namespace pcskeleton
