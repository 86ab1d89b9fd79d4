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
#include "pcskeleton/skeleton/skeleton_graph.h"
#include "pcskeleton/analysis/skeleton_quality.h"

namespace pcskeleton {

struct ThinningParameters {
    // Radius r of the sampling balls, as a fraction of the input's bounding-box diagonal
    // (the paper's 0.02). Larger: fewer nodes, small loops and close parts merge;
    // smaller: more nodes, noise may survive as spurs and tiny loops.
    double sampleRadius = 0.02;
    // Extend each limb to the end of its tip's points (tip_extension.h): contraction
    // leaves limbs short. On by default: the robustness suite (bench_robustness) measures
    // the gap to the shapes' ends with and without.
    bool extendTips = true;
    // 1-ring neighbours whose contracted points ended more than this many sample radii
    // apart were pulled to different bones (parts that touch, noise across a gap): they
    // connect their nodes only where nothing else does, so they close no cycle. 0 = every
    // 1-ring pair connects, the paper's rule. 4 by bench_robustness (--no-link-limit against
    // the default): it removes the false loops of 3 cases of 132 (three rings with 5%
    // outliers, the elephant under 2% noise, the knot with 1% outliers) and breaks none;
    // 1.5-2 cut real bones of parts that contracted less.
    double linkLimit = 4.0;
    // Remove spurs, redundant limbs and loops without a hole, merge close junctions
    // (skeleton_refinement.h). On by default: on the robustness suite (bench_robustness
    // --no-refine against the default) it turns 6 wrong topologies of 132 right (spurs from
    // misaligned and one-view scans) and none wrong.
    bool refine = true;
    // Move nodes whose points cover one side of their bone only (one-view scans, holes) to
    // the centre of the circle through those points (node_recentering.h).
    bool recentre = true;
};

struct SkeletonParameters {
    ContractionParameters contraction;
    ThinningParameters thinning;

    // Turns off every step that is not the paper's (outlier detection, denoising, the
    // stretched-link limit, re-centring, refinement, tip extension), keeping every other
    // setting.
    void keepToThePaper() {
        contraction.outliers.detect = false;
        contraction.denoisingPasses = 0;
        thinning.recentre = false;
        thinning.refine = false;
        thinning.extendTips = false;
        thinning.linkLimit = 0;
    }
    // The paper's pipeline exactly, with its defaults.
    static SkeletonParameters paper() {
        SkeletonParameters p;
        p.keepToThePaper();
        return p;
    }
};

struct StageSeconds {
    double neighbourhoods = 0, contraction = 0, thinning = 0, embedding = 0;
    double finishing = 0;  // refinement, tip extension and quality checks
};

struct SkeletonResult {
    SkeletonGraph skeleton;
    SkeletonQuality quality;
    ContractionResult contraction;  // no iterations (stop reason NotStopped) when thinned from saved contracted points
    StageSeconds seconds;
};

// Throws InvalidInput for parameters thinning cannot use; call it before a long
// contraction whose result would be thinned with them.
void checkThinningParameters(const ThinningParameters& parameters);

SkeletonResult computeCurveSkeleton(const PointList& input, const SkeletonParameters& parameters = {},
                                    const ProgressCallback& progress = {});

// Steps 4-5 and what follows them, on the current state of a contraction.
SkeletonResult skeletonFromContraction(const LaplacianContraction& contraction, const ThinningParameters& parameters,
                                       const ProgressCallback& progress = {});

// The same for `contracted` (one point per input point, same order) made earlier from
// `input` with `contraction`'s parameters: the 1-rings and the outliers are found again with
// its k (0 = the paper's rule) and outlier parameters.
SkeletonResult skeletonFromContractedPoints(const PointList& input, const PointList& contracted,
                                            const ContractionParameters& contraction,
                                            const ThinningParameters& parameters,
                                            const ProgressCallback& progress = {});

}  // namespace pcskeleton
