#include "pcskeleton/reconstruction/field_fitting.h"

#include "pcskeleton/internal/sparse_spd_solver.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

namespace pcskeleton {

namespace {

using Vector = Eigen::VectorXd;

// Node-wise vector work on every core: Eigen runs coefficient-wise expressions on one
// thread, and at fine grids they are a large share of the solve (docs/benchmarks.md#measurements-behind-the-constants).
template <class Body>
void forEachNode(Eigen::Index size, Body&& body) {
#pragma omp parallel for schedule(static)
    for (Eigen::Index n = 0; n < size; ++n) body(n);
}

// Σ term(n) over the nodes, summed in fixed blocks and then the blocks in order: the same
// value on any number of threads, so a surface does not depend on the machine's cores.
template <class Term>
double sumOverNodes(Eigen::Index size, Term&& term) {
    constexpr Eigen::Index kBlock = 1 << 14;
    const Eigen::Index blocks = (size + kBlock - 1) / kBlock;
    std::vector<double> partial(std::size_t(blocks), 0.0);
#pragma omp parallel for schedule(static)
    for (Eigen::Index b = 0; b < blocks; ++b) {
        double sum = 0;
        for (Eigen::Index n = b * kBlock; n < std::min(size, (b + 1) * kBlock); ++n) sum += term(n);
        partial[std::size_t(b)] = sum;
    }
    double sum = 0;
    for (double p : partial) sum += p;
    return sum;
}

double dot(const Vector& u, const Vector& v) {
    return sumOverNodes(u.size(), [&](Eigen::Index n) { return u[n] * v[n]; });
}

// A point constraint as one level sees it: the first node of its cell and where in the
// cell it lies. Kept small because the solver re-reads it on every operator application.
struct CellPosition {
    std::uint32_t firstNode;
    float fx, fy, fz;
};

CellPosition cellPosition(const FieldGrid& grid, const Point& p) {
    std::array<int, 3> cell{};
    std::array<float, 3> fraction{};
    for (int axis = 0; axis < 3; ++axis) {
        const double t = (p[axis] - grid.origin[axis]) / grid.spacing;
        cell[axis] = std::min(std::max(int(std::floor(t)), 0), grid.nodes[axis] - 2);
        fraction[axis] = float(std::min(std::max(t - cell[axis], 0.0), 1.0));
    }
    return {std::uint32_t(grid.index(cell[0], cell[1], cell[2])), fraction[0], fraction[1], fraction[2]};
}

// Visits the eight (node, weight) pairs of a point's trilinear interpolation.
template <class Visit>
inline void forEachCorner(const FieldGrid& grid, const CellPosition& c, Visit&& visit) {
    const std::size_t sy = grid.nodes[0], sz = std::size_t(grid.nodes[0]) * grid.nodes[1];
    const double wx[2] = {1.0 - c.fx, c.fx}, wy[2] = {1.0 - c.fy, c.fy}, wz[2] = {1.0 - c.fz, c.fz};
    for (int dk = 0; dk < 2; ++dk)
        for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di)
                visit(c.firstNode + di + dj * sy + dk * sz, wx[di] * wy[dj] * wz[dk]);
}

// out = finish(n, L̃u) at interior nodes and 0 on the boundary (interiorOnly), or finish
// of the 7-point graph Laplacian of u over the nodes that exist (the transpose of the
// former, applied to a vector that vanishes on the boundary). L̃ is the Laplacian times h².
// `finish` lets the caller complete a node's value in the same pass over memory.
template <bool interiorOnly, class Finish>
void laplacian(const FieldGrid& grid, const double* u, double* out, Finish&& finish) {
    const int nx = grid.nodes[0], ny = grid.nodes[1], nz = grid.nodes[2];
    const std::ptrdiff_t sy = nx, sz = std::ptrdiff_t(nx) * ny;
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nz; ++k) {
        for (int j = 0; j < ny; ++j) {
            const std::size_t row = grid.index(0, j, k);
            const bool interiorRow = j > 0 && j < ny - 1 && k > 0 && k < nz - 1;
            for (int i = 0; i < nx; ++i) {
                const std::size_t n = row + i;
                if (interiorRow && i > 0 && i < nx - 1) {
                    out[n] = finish(n, u[n - 1] + u[n + 1] + u[n - sy] + u[n + sy] + u[n - sz] + u[n + sz] - 6.0 * u[n]);
                } else if (interiorOnly) {
                    out[n] = 0.0;
                } else {
                    double sum = -6.0 * u[n];
                    if (i > 0) sum += u[n - 1];
                    if (i < nx - 1) sum += u[n + 1];
                    if (j > 0) sum += u[n - sy];
                    if (j < ny - 1) sum += u[n + sy];
                    if (k > 0) sum += u[n - sz];
                    if (k < nz - 1) sum += u[n + sz];
                    out[n] = finish(n, sum);
                }
            }
        }
    }
}

// One level of the multigrid hierarchy: the same energy, re-discretised.
struct Level {
    FieldGrid grid;
    double smoothScale = 0;  // w_smooth h³ / h⁴: the weight of (L̃u)² at a node
    std::vector<CellPosition> points;
    const std::vector<PointConstraint>* constraints = nullptr;
    Vector nodeWeight;  // empty = none
    Vector inverseDiagonal;
    double lambdaMax = 0;  // of D⁻¹A, for the Chebyshev smoother
    mutable Vector scratch, scratch2, residual, correction, rhs, solution;

    std::size_t size() const { return grid.size(); }

    void apply(const Vector& u, Vector& out) const {
        scratch.resize(u.size());
        out.resize(u.size());
        laplacian<true>(grid, u.data(), scratch.data(), [](std::size_t, double value) { return value; });
        if (nodeWeight.size())
            laplacian<false>(grid, scratch.data(), out.data(), [&](std::size_t n, double value) {
                return smoothScale * value + nodeWeight[Eigen::Index(n)] * u[Eigen::Index(n)];
            });
        else
            laplacian<false>(grid, scratch.data(), out.data(), [&](std::size_t, double value) { return smoothScale * value; });
        for (std::size_t p = 0; p < points.size(); ++p) {
            const double w = (*constraints)[p].weight;
            double value = 0;
            forEachCorner(grid, points[p], [&](std::size_t n, double s) { value += s * u[n]; });
            forEachCorner(grid, points[p], [&](std::size_t n, double s) { out[n] += w * s * value; });
        }
    }

    Vector diagonal() const {
        Vector d(size());
        const int nx = grid.nodes[0], ny = grid.nodes[1], nz = grid.nodes[2];
        auto interior = [&](int i, int j, int k) {
            return i > 0 && j > 0 && k > 0 && i < nx - 1 && j < ny - 1 && k < nz - 1;
        };
#pragma omp parallel for schedule(static)
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) {
                    // Column n of L̃ has -6 in row n (if interior) and 1 in each interior neighbour's row.
                    double sumOfSquares = interior(i, j, k) ? 36.0 : 0.0;
                    sumOfSquares += interior(i - 1, j, k) + interior(i + 1, j, k) + interior(i, j - 1, k) +
                                    interior(i, j + 1, k) + interior(i, j, k - 1) + interior(i, j, k + 1);
                    d[grid.index(i, j, k)] = smoothScale * sumOfSquares;
                }
        if (nodeWeight.size()) d += nodeWeight;
        for (std::size_t p = 0; p < points.size(); ++p) {
            const double w = (*constraints)[p].weight;
            forEachCorner(grid, points[p], [&](std::size_t n, double s) { d[n] += w * s * s; });
        }
        return d;
    }
};

// The finest level's node weights (empty when the problem has none).
Vector nodeWeightsOf(const FieldProblem& problem) {
    if (problem.nodeWeight.empty()) return {};
    return Eigen::Map<const Vector>(problem.nodeWeight.data(), Eigen::Index(problem.nodeWeight.size()));
}

Level makeLevel(const FieldProblem& problem, const FieldGrid& grid, Vector nodeWeight) {
    Level level;
    level.grid = grid;
    level.smoothScale = problem.smoothnessWeight / grid.spacing;
    level.constraints = &problem.pointConstraints;
    level.points.reserve(problem.pointConstraints.size());
    for (const PointConstraint& c : problem.pointConstraints) level.points.push_back(cellPosition(grid, c.position));
    level.nodeWeight = std::move(nodeWeight);
    return level;
}

// The coarse nodes a fine node interpolates along one axis: itself at an even index, its
// two neighbours halfway at an odd one.
struct AxisStencil {
    int node[2];
    double weight[2];
    int count;
};
inline AxisStencil axisStencil(int fineIndex) {
    if (fineIndex % 2 == 0) return {{fineIndex / 2, 0}, {1.0, 0.0}, 1};
    return {{fineIndex / 2, fineIndex / 2 + 1}, {0.5, 0.5}, 2};
}

// Trilinear interpolation from a level to the next finer one, added into `fineValues`.
void prolongateAdd(const FieldGrid& coarse, const FieldGrid& fine, const Vector& coarseValues, Vector& fineValues) {
    const int nx = fine.nodes[0], ny = fine.nodes[1], nz = fine.nodes[2];
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const AxisStencil si = axisStencil(i), sj = axisStencil(j), sk = axisStencil(k);
                double value = 0;
                for (int c = 0; c < sk.count; ++c)
                    for (int b = 0; b < sj.count; ++b)
                        for (int a = 0; a < si.count; ++a)
                            value += si.weight[a] * sj.weight[b] * sk.weight[c] *
                                     coarseValues[coarse.index(si.node[a], sj.node[b], sk.node[c])];
                fineValues[fine.index(i, j, k)] += value;
            }
}

// The transpose of prolongation: full weighting of a fine vector onto the coarse nodes.
Vector restrictTo(const FieldGrid& coarse, const FieldGrid& fine, const Vector& fineValues) {
    Vector result(coarse.size());
    const int nx = coarse.nodes[0], ny = coarse.nodes[1], nz = coarse.nodes[2];
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                double sum = 0;
                for (int dk = -1; dk <= 1; ++dk) {
                    const int fk = 2 * k + dk;
                    if (fk < 0 || fk >= fine.nodes[2]) continue;
                    for (int dj = -1; dj <= 1; ++dj) {
                        const int fj = 2 * j + dj;
                        if (fj < 0 || fj >= fine.nodes[1]) continue;
                        for (int di = -1; di <= 1; ++di) {
                            const int fi = 2 * i + di;
                            if (fi < 0 || fi >= fine.nodes[0]) continue;
                            const double w = (di ? 0.5 : 1.0) * (dj ? 0.5 : 1.0) * (dk ? 0.5 : 1.0);
                            sum += w * fineValues[fine.index(fi, fj, fk)];
                        }
                    }
                }
                result[coarse.index(i, j, k)] = sum;
            }
    return result;
}

// Largest eigenvalue of D⁻¹A by power iteration, with a margin: Chebyshev smoothing must
// not under-estimate it.
double estimateLambdaMax(const Level& level) {
    Vector v(level.size()), av;
    std::uint32_t state = 12345u;
    for (Eigen::Index n = 0; n < v.size(); ++n) {
        state = state * 1664525u + 1013904223u;
        v[n] = double(state >> 8) / double(1u << 24) - 0.5;
    }
    const Vector& inverseDiagonal = level.inverseDiagonal;
    double lambda = 1;
    for (int iteration = 0; iteration < 12; ++iteration) {
        level.apply(v, av);
        // The Rayleigh quotient of the pencil (A, D), then v = D⁻¹Av normalised.
        lambda = dot(v, av) / sumOverNodes(v.size(), [&](Eigen::Index n) { return v[n] * v[n] / inverseDiagonal[n]; });
        const double norm =
            std::sqrt(sumOverNodes(v.size(), [&](Eigen::Index n) { return std::pow(inverseDiagonal[n] * av[n], 2); }));
        forEachNode(v.size(), [&](Eigen::Index n) { v[n] = inverseDiagonal[n] * av[n] / norm; });
    }
    return 1.15 * lambda;
}

class MultigridPreconditioner {
public:
    MultigridPreconditioner(const FieldProblem& problem, int& levelCount) {
        FieldGrid grid = problem.grid;
        Vector nodeWeight = nodeWeightsOf(problem);
        levels_.push_back(makeLevel(problem, grid, nodeWeight));
        while (grid.canCoarsen() && grid.size() > kCoarsestNodes) {
            const FieldGrid coarse = grid.coarser();
            // Lumped Galerkin weights: a coarse node carries the fine weights it interpolates to.
            Vector coarseWeight = nodeWeight.size() ? restrictTo(coarse, grid, nodeWeight) : Vector();
            levels_.push_back(makeLevel(problem, coarse, coarseWeight));
            grid = coarse;
            nodeWeight = std::move(coarseWeight);
        }
        for (Level& level : levels_) {
            const Vector d = level.diagonal();
            // The grid's edges and corners have no interior neighbour: only node constraints reach them.
            if ((d.array() <= 0).any())
                throw InvalidInput("The field has grid nodes that no term of the energy reaches: constrain the boundary.");
            level.inverseDiagonal = d.cwiseInverse();
        }
        for (std::size_t l = 0; l + 1 < levels_.size(); ++l) levels_[l].lambdaMax = estimateLambdaMax(levels_[l]);
        coarsest_ = std::make_unique<SparseSpdSolver>(LinearSolver::Cholmod);
        if (!coarsest_->factorize(assemble(levels_.back())))
            throw InvalidInput("The reconstruction problem is singular: it has no constraint that fixes the field.");
        levelCount = int(levels_.size());
    }

    // z = M⁻¹ r: one V-cycle from zero.
    void apply(const Vector& r, Vector& z) const {
        levels_[0].rhs = r;
        vcycle(0);
        z.swap(levels_[0].solution);  // the next cycle starts from zero anyway
    }

    const Level& finest() const { return levels_[0]; }

    static Eigen::SparseMatrix<double> assemble(const Level& level) {
        const FieldGrid& grid = level.grid;
        std::vector<Eigen::Triplet<double>> triplets;
        const int nx = grid.nodes[0], ny = grid.nodes[1], nz = grid.nodes[2];
        for (int k = 1; k < nz - 1; ++k)
            for (int j = 1; j < ny - 1; ++j)
                for (int i = 1; i < nx - 1; ++i) {
                    const std::size_t n = grid.index(i, j, k);
                    const std::array<std::pair<std::size_t, double>, 7> row{{{n, -6.0},
                                                                             {n - 1, 1.0},
                                                                             {n + 1, 1.0},
                                                                             {grid.index(i, j - 1, k), 1.0},
                                                                             {grid.index(i, j + 1, k), 1.0},
                                                                             {grid.index(i, j, k - 1), 1.0},
                                                                             {grid.index(i, j, k + 1), 1.0}}};
                    for (const auto& a : row)
                        for (const auto& b : row)
                            triplets.emplace_back(int(a.first), int(b.first), level.smoothScale * a.second * b.second);
                }
        for (Eigen::Index n = 0; n < level.nodeWeight.size(); ++n)
            if (level.nodeWeight[n] != 0) triplets.emplace_back(int(n), int(n), level.nodeWeight[n]);
        for (std::size_t p = 0; p < level.points.size(); ++p) {
            const double w = (*level.constraints)[p].weight;
            forEachCorner(grid, level.points[p], [&](std::size_t a, double sa) {
                forEachCorner(grid, level.points[p], [&](std::size_t b, double sb) {
                    triplets.emplace_back(int(a), int(b), w * sa * sb);
                });
            });
        }
        Eigen::SparseMatrix<double> matrix(Eigen::Index(grid.size()), Eigen::Index(grid.size()));
        matrix.setFromTriplets(triplets.begin(), triplets.end());
        return matrix;
    }

private:
    static constexpr std::size_t kCoarsestNodes = 1000;
    static constexpr int kSmoothingDegree = 3;
    static constexpr double kSmoothingRange = 15.0;  // smooth eigenvalues in [λmax/15, λmax]

    // x += p(D⁻¹A) D⁻¹ (b − A x), p the Chebyshev polynomial damping the upper spectrum.
    static void smooth(const Level& level, bool fromZero) {
        const double upper = level.lambdaMax, lower = upper / kSmoothingRange;
        const double theta = 0.5 * (upper + lower), delta = 0.5 * (upper - lower);
        Vector& x = level.solution;
        Vector& r = level.residual;
        Vector& d = level.correction;
        const Vector& b = level.rhs;
        const Vector& inverseDiagonal = level.inverseDiagonal;
        const Eigen::Index size = Eigen::Index(level.size());
        x.resize(size);
        d.resize(size);
        if (fromZero) {
            r.resize(size);
            forEachNode(size, [&](Eigen::Index n) {
                x[n] = 0;
                r[n] = b[n];
                d[n] = inverseDiagonal[n] * r[n] / theta;
            });
        } else {
            level.apply(x, r);
            forEachNode(size, [&](Eigen::Index n) {
                r[n] = b[n] - r[n];
                d[n] = inverseDiagonal[n] * r[n] / theta;
            });
        }
        double rhoOld = delta / theta;
        for (int step = 1; step < kSmoothingDegree; ++step) {
            const Vector& ad = level.scratch2;
            level.apply(d, level.scratch2);
            const double rho = 1.0 / (2.0 * theta / delta - rhoOld);
            forEachNode(size, [&](Eigen::Index n) {
                x[n] += d[n];
                r[n] -= ad[n];
                d[n] = (rho * rhoOld) * d[n] + (2.0 * rho / delta) * inverseDiagonal[n] * r[n];
            });
            rhoOld = rho;
        }
        forEachNode(size, [&](Eigen::Index n) { x[n] += d[n]; });
    }

    void vcycle(std::size_t l) const {
        const Level& level = levels_[l];
        if (l + 1 == levels_.size()) {
            level.solution = coarsest_->solve(level.rhs);
            return;
        }
        smooth(level, true);
        Vector& residual = level.residual;
        level.apply(level.solution, residual);
        forEachNode(residual.size(), [&](Eigen::Index n) { residual[n] = level.rhs[n] - residual[n]; });
        Level& coarse = levels_[l + 1];
        coarse.rhs = restrictTo(coarse.grid, level.grid, residual);
        vcycle(l + 1);
        prolongateAdd(coarse.grid, level.grid, coarse.solution, level.solution);
        smooth(level, false);
    }

    mutable std::vector<Level> levels_;
    std::unique_ptr<SparseSpdSolver> coarsest_;
};

void checkProblem(const FieldProblem& problem) {
    const FieldGrid& grid = problem.grid;
    for (int n : grid.nodes)
        if (n < 3) throw InvalidInput("The reconstruction grid needs at least 3 nodes on each axis.");
    if (!(grid.spacing > 0) || !std::isfinite(grid.spacing))
        throw InvalidInput("The reconstruction grid spacing must be positive.");
    if (grid.size() >= (std::size_t(1) << 31))
        throw InvalidInput("The reconstruction grid is too large (" + std::to_string(grid.size()) + " nodes).");
    if (!problem.nodeWeight.empty() &&
        (problem.nodeWeight.size() != grid.size() || problem.nodeValue.size() != grid.size()))
        throw InvalidInput("Node constraints must give one weight and one value per grid node.");
}

}  // namespace

std::vector<double> interpolateToFiner(const FieldGrid& coarse, const FieldGrid& fine, const std::vector<double>& values) {
    if (values.size() != coarse.size() || fine.coarser().size() != coarse.size())
        throw InvalidInput("interpolateToFiner: the grids do not match.");
    Vector result = Vector::Zero(Eigen::Index(fine.size()));
    prolongateAdd(coarse, fine, Eigen::Map<const Vector>(values.data(), values.size()), result);
    return std::vector<double>(result.data(), result.data() + result.size());
}

Eigen::VectorXd fieldRightHandSide(const FieldProblem& problem) {
    checkProblem(problem);
    Vector b = Vector::Zero(Eigen::Index(problem.grid.size()));
    for (std::size_t n = 0; n < problem.nodeWeight.size(); ++n) b[n] = problem.nodeWeight[n] * problem.nodeValue[n];
    for (const PointConstraint& c : problem.pointConstraints)
        forEachCorner(problem.grid, cellPosition(problem.grid, c.position),
                      [&](std::size_t n, double s) { b[n] += c.weight * c.value * s; });
    return b;
}

Eigen::SparseMatrix<double> assembleFieldMatrix(const FieldProblem& problem) {
    checkProblem(problem);
    return MultigridPreconditioner::assemble(makeLevel(problem, problem.grid, nodeWeightsOf(problem)));
}

Eigen::VectorXd applyFieldMatrix(const FieldProblem& problem, const Eigen::VectorXd& u) {
    checkProblem(problem);
    Vector result;
    makeLevel(problem, problem.grid, nodeWeightsOf(problem)).apply(u, result);
    return result;
}

std::vector<double> solveField(const FieldProblem& problem, const std::vector<double>& initialGuess,
                               const FieldSolverOptions& options, FieldSolveReport& report,
                               const ProgressCallback& progress) {
    checkProblem(problem);
    if (!initialGuess.empty() && initialGuess.size() != problem.grid.size())
        throw InvalidInput("The initial guess must give one value per grid node.");
    report = FieldSolveReport{};
    const MultigridPreconditioner preconditioner(problem, report.levels);
    const Level& finest = preconditioner.finest();
    const Vector b = fieldRightHandSide(problem);
    Vector x = initialGuess.empty() ? Vector::Zero(b.size())
                                    : Eigen::Map<const Vector>(initialGuess.data(), initialGuess.size()).eval();
    const double bNorm = b.norm();
    if (bNorm == 0) {
        report.converged = true;
        return std::vector<double>(b.size(), 0.0);
    }
    Vector r, z, ap;
    finest.apply(x, ap);
    r = b - ap;
    preconditioner.apply(r, z);
    Vector p = z;
    double rz = dot(r, z);
    const double initialResidual = std::sqrt(dot(r, r)) / bNorm;
    for (;;) {
        report.relativeResidual = std::sqrt(dot(r, r)) / bNorm;
        if (report.relativeResidual <= options.tolerance) {
            report.converged = true;
            break;
        }
        if (report.iterations >= options.maxIterations) break;
        if (progress && initialResidual > options.tolerance) {
            const double done = std::log(initialResidual / report.relativeResidual) /
                                std::log(initialResidual / options.tolerance);
            pcskeleton::report(progress, int(100 * std::min(std::max(done, 0.0), 1.0)), "Solving for the field");
        }
        finest.apply(p, ap);
        const double pap = dot(p, ap);
        if (!(pap > 0))
            throw InvalidInput("The reconstruction problem is not positive definite: too few constraints fix the field.");
        const double alpha = rz / pap;
        forEachNode(x.size(), [&](Eigen::Index n) {
            x[n] += alpha * p[n];
            r[n] -= alpha * ap[n];
        });
        preconditioner.apply(r, z);
        const double rzNext = dot(r, z);
        const double beta = rzNext / rz;
        forEachNode(p.size(), [&](Eigen::Index n) { p[n] = z[n] + beta * p[n]; });
        rz = rzNext;
        ++report.iterations;
    }
    return std::vector<double>(x.data(), x.data() + x.size());
}

}  // namespace pcskeleton
