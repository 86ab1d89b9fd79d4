// Step 3 of the paper (Sec. III-A): iterative Laplacian contraction of a point cloud.
//
// Each iteration solves, in least squares,
//     [ W_L L ]        [   0   ]
//     [  W_H  ] P'  =  [ W_H P ]
// i.e. (W_L^2 L^T L + W_H^2) P' = W_H^2 P for x, y and z with one factorisation, then
// sets W_L <- s_L W_L and W_H,i <- W_H0 S_i^0 / S_i^t, where S_i is the extent of point
// i's 1-ring. It stops when, once the contraction has started, the total 1-ring extent
// shrinks by less than the threshold (relative to the start) in an iteration; on the
// iteration limit; or on a numerical failure (the last good positions are kept).
// With a medial pull W_M (not in the paper, off by default), the pulled points' rows also
// get W_M² on the diagonal and W_M² m on the right, m their medial centre (medial_pull.h).
//
// One-call use:   ContractionResult r = LaplacianContraction::run(points);
// Step by step:   LaplacianContraction c(points);
//                 while (!c.finished()) { auto report = c.iterate(); ... c.contractedPoints(); }
#pragma once

#include "pcskeleton/contraction/cotangent_laplacian.h"
#include "pcskeleton/contraction/medial_pull.h"
#include "pcskeleton/contraction/one_ring.h"
#include "pcskeleton/contraction/point_denoising.h"
#include "pcskeleton/contraction/point_cloud_input.h"
#include "pcskeleton/core/progress.h"
#include "pcskeleton/internal/sparse_spd_solver.h"

#include <memory>
#include <string>
#include <vector>

namespace pcskeleton {

class GramMatrix;

// Defaults are the paper's (and its authors' reference code's). Lengths are measured
// in the normalised frame of NormalizedCloud, so the defaults do not depend on units.
struct ContractionParameters {
    int neighbourCount = 0;                 // k; 0 = automatic: defaultNeighbourCount (one_ring.h)
    bool papersNeighbourRule = false;       // automatic k by the paper's rule, which has fewer
                                            // neighbours below 1667 points
    double initialContractionWeight = 0.0;  // W_L0; 0 = 1 / (5 S0), S0 = mean 1-ring extent
    double initialAttractionWeight = 1.0;   // W_H0
    double contractionScale = 3.0;          // s_L, W_L grows by this factor per iteration
    double maxContractionWeight = 2048.0;   // cap on W_L
    double maxAttractionWeight = 10000.0;   // cap on each W_H,i
    double laplacianRowLimit = 10000.0;     // cap on a Laplacian row's absolute weight sum
    int maxIterations = 20;
    double terminationThreshold = 0.01;     // stop when the extent ratio falls by less than this
    OutlierParameters outliers;             // points set aside before the 1-rings (not the paper's)
    int denoisingPasses = -1;               // contract a denoised copy (point_denoising.h): -1 = only
                                            // noisy clouds, 0 = never (the paper's), 1..10 passes
    bool separateFacingWalls = true;        // 1-rings leave out neighbours on a wall facing the
                                            // point's own (facing_walls.h); off in the paper
    double medialPull = 0.0;                // W_M, the pull towards each point's medial centre
                                            // (medial_pull.h); 0 = none, as in the paper
    LinearSolver solver = LinearSolver::Automatic;  // no BLAS up to 20K points: the same on every CPU
};

// Throws InvalidInput naming the first unusable parameter.
void checkContractionParameters(const ContractionParameters& parameters);

enum class StopReason {
    NotStopped,
    Converged,        // the 1-ring extents stopped shrinking
    IterationLimit,   // maxIterations reached
    NumericalFailure  // the solve failed or diverged; the previous positions are kept
};

std::string describe(StopReason reason);

struct IterationReport {
    int iteration = 0;               // 1-based
    double extentRatio = 1.0;        // sum of S_i^t / sum of S_i^0 after this iteration
    double contractionWeight = 0.0;  // W_L used by this iteration
    double seconds = 0.0;
};

// How a contraction ended: what the quality report tells of it.
struct ContractionOutcome {
    StopReason stopReason = StopReason::NotStopped;
    int iterations = 0;
    double extentRatio = 1.0;  // mean 1-ring size at the end, relative to the start
    int denoisingPasses = 0;   // of the copy whose 1-rings were contracted (point_denoising.h)
    double surfaceNoise = -1;  // measured for the automatic choice, else -1
    long facingNeighboursLeftOut = -1;  // of the 1-rings (facing_walls.h); -1 when not separated
    long medialPullPoints = -1;  // points pulled towards a medial centre (medial_pull.h); -1 when off
};

struct ContractionResult {
    PointList contracted;  // one per input point, in the input's frame and order
    std::vector<IterationReport> iterations;
    StopReason stopReason = StopReason::NotStopped;
    int neighbourCount = 0;
    double initialContractionWeight = 0.0;
    double neighbourhoodSeconds = 0.0;
    int denoisingPasses = 0;
    double surfaceNoise = -1;  // measured for the automatic choice, else -1
    long facingNeighboursLeftOut = -1;  // of the 1-rings (facing_walls.h); -1 when not separated
    long medialPullPoints = -1;  // points pulled towards a medial centre (medial_pull.h); -1 when off

    ContractionOutcome outcome() const;
};

// What the contraction starts from: the normalised cloud (outliers set aside), the
// denoising chosen for it, the starting positions (the denoised copy) and their 1-rings.
// Thinning saved contracted points must rebuild exactly this, hence one function for both.
// Of the parameters only k, the outlier parameters, the denoising passes and the facing
// walls are used.
struct ContractionStart {
    NormalizedCloud cloud;
    DenoisingChoice denoising;
    PointList positions;
    OneRings rings;
    double neighbourhoodSeconds = 0.0;  // denoising and 1-rings
};
ContractionStart prepareContraction(const PointList& input, const ContractionParameters& parameters,
                                    const ProgressCallback& progress = {});
// What the reports say of the facing walls: the neighbours left out, or -1 when not separated.
long facingNeighboursLeftOut(const ContractionParameters& parameters, const OneRings& rings);

class LaplacianContraction {
public:
    // Validates the input and the parameters and refuses work larger than memory (throws
    // InvalidInput), then computes the 1-rings (step 1).
    explicit LaplacianContraction(const PointList& input, const ContractionParameters& parameters = {},
                                  const ProgressCallback& progress = {});
    ~LaplacianContraction();

    // One contraction iteration; once finished(), changes nothing and returns the last report.
    IterationReport iterate();
    // Iterates until finished(); progress 0-100% over the iteration limit.
    void iterateToEnd(const ProgressCallback& progress = {});
    bool finished() const { return stopReason_ != StopReason::NotStopped; }
    StopReason stopReason() const { return stopReason_; }

    // Current positions, one per input point (duplicates get their twin's), input frame.
    PointList contractedPoints() const;
    // Current positions of the distinct points, normalised frame (what rings() index).
    const PointList& normalizedPositions() const { return positions_; }
    const NormalizedCloud& cloud() const { return cloud_; }
    // The distinct points as contraction started from them, normalised frame: the denoised
    // copy when the cloud was denoised, else the cloud's points.
    const PointList& startPositions() const { return denoisedStart_.empty() ? cloud_.points : denoisedStart_; }
    const OneRings& rings() const { return rings_; }

    const std::vector<IterationReport>& history() const { return history_; }
    int neighbourCount() const { return rings_.neighbourCount(); }
    double initialContractionWeight() const { return initialContractionWeight_; }
    double neighbourhoodSeconds() const { return neighbourhoodSeconds_; }

    // What the contraction produced so far.
    ContractionResult result() const;

    // Runs to the end. Progress: 0-30% neighbourhoods, then per iteration.
    static ContractionResult run(const PointList& input, const ContractionParameters& parameters = {},
                                 const ProgressCallback& progress = {});

private:
    bool solve(double contractionWeight, PointList& next);
    void updateWeights(const std::vector<double>& extents);

    ContractionParameters parameters_;
    NormalizedCloud cloud_;
    OneRings rings_;
    std::unique_ptr<CotangentLaplacian> laplacian_;
    std::unique_ptr<GramMatrix> normalEquations_;  // LᵀL, pattern analysed once
    SparseSpdSolver solver_;
    PointList positions_;
    PointList denoisedStart_;  // empty when the cloud was not denoised
    std::vector<double> initialExtents_, attractionWeights_;
    double initialExtentSum_ = 0.0;
    double contractionWeight_ = 0.0, initialContractionWeight_ = 0.0;
    double neighbourhoodSeconds_ = 0.0;
    DenoisingChoice denoising_;
    MedialTargets medialTargets_;  // empty without a medial pull
    std::vector<IterationReport> history_;
    StopReason stopReason_ = StopReason::NotStopped;
    bool contractionStarted_ = false;  // some iteration shrank the rings by the threshold
};

}  // namespace pcskeleton
