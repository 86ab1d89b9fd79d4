#include "pcskeleton/contraction/laplacian_contraction.h"

#include "pcskeleton/contraction/contraction_memory.h"

#include "pcskeleton/internal/gram_matrix.h"
#include "pcskeleton/internal/stopwatch.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <numeric>

namespace pcskeleton {

namespace {

// Positions this far out (in normalised units, where the cloud spans 1.6) mean the
// solve diverged: a contraction only ever moves points inwards.
constexpr double kDivergenceRadius = 100.0;

bool diverged(const PointList& points) {
    return std::any_of(points.begin(), points.end(), [](const Point& p) {
        return !p.allFinite() || p.lpNorm<Eigen::Infinity>() > kDivergenceRadius;
    });
}

}  // namespace

void checkContractionParameters(const ContractionParameters& p) {
    auto require = [](bool ok, Parameter parameter, const char* requirement) {
        if (!ok) throw InvalidInput(Problem::aboutParameter(parameter, requirement));
    };
    require(p.neighbourCount == 0 || p.neighbourCount >= 4, Parameter::NeighbourCount,
            "must be 0 (automatic) or at least 4.");
    // Weights are relative to the normalised cloud's (its longest side is 1.6): beyond this,
    // the other term of the system falls below the solver's precision.
    constexpr double kLargestWeight = 1e8;
    const auto weight = [&](double w) { return w > 0 && w <= kLargestWeight; };
    require(p.initialContractionWeight == 0 || weight(p.initialContractionWeight), Parameter::InitialContractionWeight,
            "must be 0 (automatic) or a positive number up to 1e8.");
    require(weight(p.initialAttractionWeight), Parameter::InitialAttractionWeight, "must be a positive number up to 1e8.");
    // Beyond a factor of 1000 a single step takes W_L from its start to its limit.
    require(p.contractionScale >= 1 && p.contractionScale <= 1000, Parameter::ContractionScale,
            "must be between 1 and 1000.");
    require(weight(p.maxContractionWeight), Parameter::MaxContractionWeight, "must be a positive number up to 1e8.");
    require(weight(p.maxAttractionWeight), Parameter::MaxAttractionWeight, "must be a positive number up to 1e8.");
    require(weight(p.laplacianRowLimit), Parameter::LaplacianRowLimit, "must be a positive number up to 1e8.");
    require(p.medialPull == 0 || weight(p.medialPull), Parameter::MedialPull, "must be 0 (none) or a positive number up to 1e8.");
    require(p.maxIterations >= 1, Parameter::MaxIterations, "must be at least 1.");
    // The extent ratio lies between 0 and 1: a threshold of 1 or more stops after one iteration.
    require(p.terminationThreshold >= 0 && p.terminationThreshold < 1, Parameter::TerminationThreshold,
            "must be at least 0 and below 1.");
    checkOutlierParameters(p.outliers);
    checkDenoisingPasses(p.denoisingPasses);
}

namespace {

int chooseNeighbourCount(const ContractionParameters& p, std::size_t inputSize) {
    if (p.neighbourCount > 0) return p.neighbourCount;
    return p.papersNeighbourRule ? paperNeighbourCount(inputSize) : defaultNeighbourCount(inputSize);
}

}  // namespace

long facingNeighboursLeftOut(const ContractionParameters& parameters, const OneRings& rings) {
    return parameters.separateFacingWalls ? long(rings.facingNeighboursLeftOut()) : -1;
}

std::string describe(StopReason reason) {
    switch (reason) {
        case StopReason::NotStopped: return "not finished";
        case StopReason::Converged: return "converged (1-ring extents stopped shrinking)";
        case StopReason::IterationLimit: return "iteration limit reached";
        case StopReason::NumericalFailure: return "numerical failure (kept the last good positions)";
    }
    return "unknown";
}

ContractionStart prepareContraction(const PointList& input, const ContractionParameters& parameters,
                                    const ProgressCallback& progress) {
    const int k = chooseNeighbourCount(parameters, input.size());
    ContractionStart start;
    start.cloud = normalizeCloud(input, static_cast<std::size_t>(k) + 1, parameters.outliers);
    const Stopwatch stopwatch;
    start.denoising = chooseDenoising(start.cloud.points, k, parameters.denoisingPasses);
    start.positions = denoisedCopy(start.cloud.points, k, start.denoising.passes);
    start.rings = OneRings::compute(
        start.positions, k, parameters.separateFacingWalls ? FacingWalls::LeaveOut : FacingWalls::Keep, progress);
    start.neighbourhoodSeconds = stopwatch.seconds();
    return start;
}

LaplacianContraction::LaplacianContraction(const PointList& input, const ContractionParameters& parameters,
                                           const ProgressCallback& progress)
    : parameters_(parameters), solver_(parameters.solver) {
    checkContractionParameters(parameters_);
    refuseWorkLargerThanMemory(input.size(), 0, 0);
    ContractionStart start = prepareContraction(input, parameters_, progress);
    cloud_ = std::move(start.cloud);
    denoising_ = start.denoising;
    positions_ = std::move(start.positions);
    if (denoising_.passes > 0) denoisedStart_ = positions_;
    rings_ = std::move(start.rings);
    neighbourhoodSeconds_ = start.neighbourhoodSeconds;

    laplacian_ = std::make_unique<CotangentLaplacian>(rings_, parameters_.laplacianRowLimit);
    normalEquations_ = std::make_unique<GramMatrix>(laplacian_->matrix());
    initialExtents_ = ringExtents(rings_, positions_);
    initialExtentSum_ = std::accumulate(initialExtents_.begin(), initialExtents_.end(), 0.0);
    if (!(initialExtentSum_ > 0)) throw InvalidInput("The points have no usable neighbourhoods.");

    const double meanExtent = initialExtentSum_ / static_cast<double>(initialExtents_.size());
    initialContractionWeight_ = parameters_.initialContractionWeight > 0 ? parameters_.initialContractionWeight
                                                                         : 1.0 / (5.0 * meanExtent);
    contractionWeight_ = initialContractionWeight_;
    attractionWeights_.assign(positions_.size(), parameters_.initialAttractionWeight);
    if (parameters_.medialPull > 0) medialTargets_ = estimateMedialTargets(positions_);
}

LaplacianContraction::~LaplacianContraction() = default;

bool LaplacianContraction::solve(double contractionWeight, PointList& next) {
    // W_L² LᵀL + W_H², lower triangle, filled in place: the pattern is the same every time.
    laplacian_->update(positions_);
    normalEquations_->update(laplacian_->matrix(), contractionWeight * contractionWeight);
    SparseSpdSolver::Matrix& system = normalEquations_->matrix();

    const Eigen::Index n = static_cast<Eigen::Index>(positions_.size());
    Eigen::MatrixXd rhs(n, 3);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double w2 = attractionWeights_[i] * attractionWeights_[i];
        system.valuePtr()[normalEquations_->diagonalSlot(int(i))] += w2;
        rhs.row(i) = w2 * positions_[i].transpose();
    }
    if (!medialTargets_.empty()) {
        const double m2 = parameters_.medialPull * parameters_.medialPull;
        for (Eigen::Index i = 0; i < n; ++i) {
            if (!medialTargets_.found[std::size_t(i)]) continue;
            system.valuePtr()[normalEquations_->diagonalSlot(int(i))] += m2;
            rhs.row(i) += m2 * medialTargets_.centres[std::size_t(i)].transpose();
        }
    }
    Eigen::MatrixXd solution;
    try {
        if (!solver_.factorize(system)) return false;
        solution = solver_.solve(rhs);
    } catch (const std::bad_alloc&) {
        // Not a numerical failure, and the contraction could not go on: say what ran out.
        throw InvalidInput("Out of memory: the factorisation of the contraction's " + std::to_string(n) +
                               " unknowns needs more memory than this process may use.",
                           {Remedy::lower(Parameter::ContractedPoints)});
    }
    next.resize(positions_.size());
    for (Eigen::Index i = 0; i < n; ++i) next[i] = solution.row(i).transpose();
    return !diverged(next);
}

void LaplacianContraction::updateWeights(const std::vector<double>& extents) {
    for (std::size_t i = 0; i < extents.size(); ++i) {
        double w = parameters_.initialAttractionWeight;
        if (initialExtents_[i] > 0) {
            w = extents[i] > 0 ? w * initialExtents_[i] / extents[i] : parameters_.maxAttractionWeight;
        }
        attractionWeights_[i] = std::min(w, parameters_.maxAttractionWeight);
    }
    contractionWeight_ = std::min(contractionWeight_ * parameters_.contractionScale, parameters_.maxContractionWeight);
}

IterationReport LaplacianContraction::iterate() {
    if (finished()) return history_.back();
    const Stopwatch stopwatch;
    IterationReport report;
    report.iteration = static_cast<int>(history_.size()) + 1;
    report.contractionWeight = contractionWeight_;
    const double previousRatio = history_.empty() ? 1.0 : history_.back().extentRatio;

    PointList next;
    if (!solve(contractionWeight_, next)) {
        stopReason_ = StopReason::NumericalFailure;
        report.extentRatio = previousRatio;
        report.seconds = stopwatch.seconds();
        history_.push_back(report);
        return report;
    }
    positions_.swap(next);

    const std::vector<double> extents = ringExtents(rings_, positions_);
    report.extentRatio = std::accumulate(extents.begin(), extents.end(), 0.0) / initialExtentSum_;
    updateWeights(extents);

    // Converged means the rings shrank and then stopped shrinking. Iterations before the
    // contraction starts do not count: on dense clouds the cotangent Laplacian's coordinates
    // shrink with the square of the spacing while W_L0 = 1/(5 S0) grows only with its
    // inverse, so the first iterations can barely move until W_L has grown.
    const double shrinkage = previousRatio - report.extentRatio;
    if (contractionStarted_ && shrinkage < parameters_.terminationThreshold) {
        stopReason_ = StopReason::Converged;
    } else if (report.iteration >= parameters_.maxIterations) {
        stopReason_ = StopReason::IterationLimit;
    }
    contractionStarted_ = contractionStarted_ || shrinkage >= parameters_.terminationThreshold;
    report.seconds = stopwatch.seconds();
    history_.push_back(report);
    return report;
}

PointList LaplacianContraction::contractedPoints() const {
    // Outliers are not contracted: they stay where they are.
    PointList result(cloud_.inputSize());
    for (std::size_t i = 0; i < result.size(); ++i) {
        const int unique = cloud_.uniqueIndex[i];
        result[i] = unique >= 0 ? cloud_.toInputFrame(positions_[unique]) : cloud_.inputPosition(i);
    }
    return result;
}

void LaplacianContraction::iterateToEnd(const ProgressCallback& progress) {
    while (!finished()) {
        const IterationReport r = iterate();
        report(progress, std::min(100, 100 * r.iteration / parameters_.maxIterations), "Contracting");
    }
}

ContractionOutcome ContractionResult::outcome() const {
    ContractionOutcome outcome;
    outcome.stopReason = stopReason;
    outcome.iterations = int(iterations.size());
    outcome.extentRatio = iterations.empty() ? 1.0 : iterations.back().extentRatio;
    outcome.denoisingPasses = denoisingPasses;
    outcome.surfaceNoise = surfaceNoise;
    outcome.facingNeighboursLeftOut = facingNeighboursLeftOut;
    outcome.medialPullPoints = medialPullPoints;
    return outcome;
}

ContractionResult LaplacianContraction::result() const {
    ContractionResult result;
    result.contracted = contractedPoints();
    result.iterations = history_;
    result.stopReason = stopReason_;
    result.neighbourCount = neighbourCount();
    result.initialContractionWeight = initialContractionWeight_;
    result.neighbourhoodSeconds = neighbourhoodSeconds_;
    result.denoisingPasses = denoising_.passes;
    result.surfaceNoise = denoising_.surfaceNoise;
    result.facingNeighboursLeftOut = facingNeighboursLeftOut(parameters_, rings_);
    result.medialPullPoints = parameters_.medialPull > 0 ? long(medialTargets_.count) : -1;
    return result;
}

ContractionResult LaplacianContraction::run(const PointList& input, const ContractionParameters& parameters,
                                            const ProgressCallback& progress) {
    LaplacianContraction contraction(input, parameters, progressRange(progress, 0, 30));
    contraction.iterateToEnd(progressRange(progress, 30, 100));
    return contraction.result();
}

}  // namespace pcskeleton
