// The whole pipeline, point cloud to curve skeleton: contraction (steps 1-3), thinning
// (step 4) and embedding (step 5), then the optional refinement, tip extension and the
// quality report.
//
// One call:     SkeletonResult r = computeCurveSkeleton(points);
// Two stages:   contract with LaplacianContraction (watching every iteration), then
//               skeletonFromContraction(contraction); or, for contracted points saved
//               earlier, skeletonFromContractedPoints(input, contracted).
#pragma once

#include "pcskeleton/contraction/laplacian_contraction.h"
#include "pcskeleton/contraction/point_subsampling.h"
#include "pcskeleton/skeleton/skeleton_graph.h"
#include "pcskeleton/finishing/skeleton_quality.h"
#include "pcskeleton/finishing/skeleton_refinement.h"

namespace pcskeleton {

// Everything after the contraction: thinning and embedding (steps 4-5), then the steps
// this project added. Why each default is what it is: docs/benchmarks.md.
struct SkeletonGraphParameters {
    // Radius r of the sampling balls, as a fraction of the input's bounding-box diagonal
    // (the paper's 0.02). Larger: fewer nodes, small loops and close parts merge;
    // smaller: more nodes, noise may survive as spurs and tiny loops.
    double nodeSpacing = 0.02;
    // Extend each limb to the end of its tip's points (tip_extension.h): contraction
    // leaves limbs short.
    bool extendTips = true;
    // 1-ring neighbours whose contracted points ended more than this many node spacings
    // apart were pulled to different bones (parts that touch, noise across a gap): they
    // connect their nodes only where nothing else does, so they close no cycle. 0 = every
    // 1-ring pair connects, the paper's rule.
    double linkLimit = 4.0;
    // Remove spurs, redundant limbs and loops without a hole, merge close junctions
    // (skeleton_refinement.h).
    bool refine = true;
    // Part of refinement: loops narrower than their tube opened where parts touch, bones
    // straight across a gap cut (skeleton_structure.h).
    RefinementLimits refinementLimits;
    // Move the points of wide one-layer flat sheets that contraction left flat (plates,
    // discs) onto their medial axes before thinning (sheet_collapse.h).
    bool collapseSheets = true;
    // Move nodes whose points cover one side of their bone only (one-view scans, holes) to
    // the centre of the circle through those points (node_recentering.h).
    bool recentre = true;
    // Join pieces of the skeleton across gaps in the data at most this many node spacings
    // long, from tube to tube, where a limb's end (a tip, or a corner where it turns into
    // another limb) points at another piece or a piece is a single node (gap_bridging.h).
    // 0 = no bridge, the paper's.
    double gapLimit = 8.0;
};

struct ResolutionParameters {
    // A cloud with more points than this is contracted through a well-spread subsample of
    // at most this many (point_subsampling.h), and every input point takes the node of the
    // subsample point that stands for it; radii come from all points. 0 = contract every
    // point (the paper's). Not in the paper; chosen on the robustness suite at 100K points
    // and on the paper's tree (docs/benchmarks.md).
    std::size_t maxContractedPoints = 15000;
    // The smallest subsample allowed: a few nodes' worth of points, so that the subsample
    // always has the k nearest neighbours contraction needs (at most 30 plus the point).
    static constexpr std::size_t kFewestContractedPoints = 100;
    // Work whose estimated peak memory exceeds this many bytes is refused before it starts;
    // 0 = what the machine and the process's limits allow (machine_memory.h).
    double memoryLimit = 0.0;
};
// The default subsample is solved without BLAS, so default runs give the same skeleton
// whichever kernels OpenBLAS picks for the CPU (sparse_spd_solver.h).
static_assert(ResolutionParameters{}.maxContractedPoints <= std::size_t(kLargestPortableSystem),
              "default contractions must stay within the portable solver's range");

// Throws InvalidInput naming the first unusable parameter.
void checkResolutionParameters(const ResolutionParameters& parameters);

struct SkeletonParameters {
    ContractionParameters contraction;
    SkeletonGraphParameters graph;
    ResolutionParameters resolution;

    // Turns off every step that is not the paper's (outlier detection, denoising, the facing
    // walls, the medial pull, the stretched-link limit, the sheets' medial axes, re-centring,
    // refinement, gap bridging, tip extension, the subsample) and takes its rule for an
    // automatic k, keeping every other setting.
    void keepToThePaper() {
        resolution.maxContractedPoints = 0;
        contraction.papersNeighbourRule = true;
        contraction.outliers.detect = false;
        contraction.denoisingPasses = 0;
        contraction.separateFacingWalls = false;
        contraction.medialPull = 0;
        graph.collapseSheets = false;
        graph.recentre = false;
        graph.refine = false;
        graph.extendTips = false;
        graph.linkLimit = 0;
        graph.gapLimit = 0;
    }
    // The paper's pipeline exactly, with its defaults.
    static SkeletonParameters paper() {
        SkeletonParameters p;
        p.keepToThePaper();
        return p;
    }
};

struct StageSeconds {
    double subsampling = 0;  // multi-resolution: outliers of the whole cloud, the grid, carrying back
    double neighbourhoods = 0, contraction = 0, thinning = 0, embedding = 0;
    double finishing = 0;  // refinement, tip extension and quality checks
};

struct SkeletonResult {
    SkeletonGraph skeleton;
    SkeletonQuality quality;
    ContractionResult contraction;  // no iterations (stop reason NotStopped) when thinned from saved contracted points
    StageSeconds seconds;
};

// The points a contraction of `input` works on: all of them, or, above
// `maxContractedPoints`, their spread subsample; then the skeleton computed from those,
// carried to every input point. Refuses (InvalidInput) a cloud whose computation would
// not fit in memory, naming the size it needs, before any work.
//
//     const ContractionInput work(points, parameters.resolution);
//     LaplacianContraction contraction(work.points(), ...);  ...
//     SkeletonResult result = skeletonFromContraction(contraction, ...);
//     work.carryToAllPoints(result);
class ContractionInput {
public:
    // `input` must outlive this object. When a subsample is taken, the outliers of the
    // whole cloud are found first (`outliers`) and get no node: a grid keeps an isolated
    // point as surely as a surface patch, so in the subsample they would weigh far more.
    ContractionInput(const PointList& input, const ResolutionParameters& parameters,
                     const OutlierParameters& outliers, const ProgressCallback& progress = {});

    const PointList& points() const { return subsampled() ? kept_ : input_; }
    bool subsampled() const { return subsampled_; }
    const PointSubsample& subsample() const { return subsample_; }

    // For a result computed on points(): the correspondence and the contracted positions
    // for every input point (its subsample point's), radii from all the points of each
    // node, and the report's input size. Nothing to do without a subsample.
    void carryToAllPoints(SkeletonResult& result) const;

private:
    const PointList& input_;
    bool subsampled_ = false;
    PointSubsample subsample_;
    std::size_t outliers_ = 0;  // of the whole cloud, left out of the subsample
    PointList kept_;
    double seconds_ = 0;
};

// Throws InvalidInput for parameters thinning cannot use; call it before a long
// contraction whose result would be thinned with them.
void checkSkeletonGraphParameters(const SkeletonGraphParameters& parameters);

// The whole computation on one cloud, in the steps a front end may want to watch or pause;
// every way of computing a skeleton goes through it.
//
//     SkeletonPipeline pipeline(points, parameters);   // checks, memory, subsample, 1-rings
//     while (!pipeline.contraction().finished()) pipeline.contraction().iterate();
//     SkeletonResult result = pipeline.skeleton();      // steps 4-5 and after, every point
//
// The constructor refuses (InvalidInput), before any long work, parameters the pipeline
// cannot use and work that would not fit in memory. `input` must outlive the pipeline.
class SkeletonPipeline {
public:
    SkeletonPipeline(const PointList& input, const SkeletonParameters& parameters,
                     const ProgressCallback& progress = {});

    const SkeletonParameters& parameters() const { return parameters_; }
    // What is contracted: every point, or the subsample.
    const ContractionInput& input() const { return input_; }
    LaplacianContraction& contraction() { return contraction_; }
    const LaplacianContraction& contraction() const { return contraction_; }

    // Steps 4-5 and what follows them on the contraction's current state, carried to every
    // input point.
    SkeletonResult skeleton(const ProgressCallback& progress = {}) const;
    // The same with other thinning parameters than the pipeline's: trying node spacings or
    // refinement on one contraction costs only these steps. Throws InvalidInput for
    // parameters thinning cannot use.
    SkeletonResult skeleton(const SkeletonGraphParameters& graph, const ProgressCallback& progress = {}) const;

private:
    SkeletonParameters parameters_;
    ContractionInput input_;
    LaplacianContraction contraction_;
};

SkeletonResult computeCurveSkeleton(const PointList& input, const SkeletonParameters& parameters = {},
                                    const ProgressCallback& progress = {});

// Steps 4-5 and what follows them, on the current state of a contraction.
SkeletonResult skeletonFromContraction(const LaplacianContraction& contraction, const SkeletonGraphParameters& parameters,
                                       const ProgressCallback& progress = {});

// The same for `contracted` (one point per input point, same order) made earlier from
// `input` with `contraction`'s parameters: the 1-rings and the outliers are found again with
// its k (0 = the paper's rule) and outlier parameters.
SkeletonResult skeletonFromContractedPoints(const PointList& input, const PointList& contracted,
                                            const ContractionParameters& contraction,
                                            const SkeletonGraphParameters& parameters,
                                            const ProgressCallback& progress = {});

// The same through the subsample computeCurveSkeleton(input, parameters) contracts, when it
// takes one: thinning the points it kept (each at its own contracted place) and carrying the
// result to every point, as that run did. With the parameters of the run that made
// `contracted`, this gives its skeleton, at the cost of thinning the subsample alone.
SkeletonResult skeletonFromContractedPoints(const PointList& input, const PointList& contracted,
                                            const SkeletonParameters& parameters,
                                            const ProgressCallback& progress = {});

}  // namespace pcskeleton
