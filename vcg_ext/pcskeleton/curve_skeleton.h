// The whole pipeline, point cloud to curve skeleton: contraction (steps 1-3), thinning
// (step 4) and embedding (step 5).
//
// One call:     SkeletonResult r = computeCurveSkeleton(points);
// Two stages:   contract with LaplacianContraction (watching every iteration), then
//               skeletonFromContraction(contraction); or, for contracted points saved
//               earlier, skeletonFromContractedPoints(input, contracted).
#pragma once

#include "pcskeleton/laplacian_contraction.h"
#include "pcskeleton/skeleton_graph.h"

namespace pcskeleton {

struct ThinningParameters {
    // Radius r of the sampling balls, as a fraction of the input's bounding-box diagonal
    // (the paper's 0.02). Larger: fewer nodes, small loops and close parts merge;
    // smaller: more nodes, noise may survive as spurs and tiny loops.
    double sampleRadius = 0.02;
};

struct SkeletonParameters {
    ContractionParameters contraction;
    ThinningParameters thinning;
};

struct StageSeconds {
    double neighbourhoods = 0, contraction = 0, thinning = 0, embedding = 0;
};

struct SkeletonResult {
    SkeletonGraph skeleton;
    ContractionResult contraction;
    StageSeconds seconds;
};

// Throws InvalidInput for parameters thinning cannot use; call it before a long
// contraction whose result would be thinned with them.
void checkThinningParameters(const ThinningParameters& parameters);

SkeletonResult computeCurveSkeleton(const PointList& input, const SkeletonParameters& parameters = {},
                                    const ProgressCallback& progress = {});

// Steps 4-5 on the current state of a contraction. Fills every stage of `seconds`.
SkeletonGraph skeletonFromContraction(const LaplacianContraction& contraction, const ThinningParameters& parameters,
                                      StageSeconds* seconds = nullptr, const ProgressCallback& progress = {});

// Steps 4-5 for `contracted` (one point per input point, same order) made earlier from
// `input`. The 1-rings are rebuilt on `input` with k neighbours (0 = the paper's rule).
SkeletonGraph skeletonFromContractedPoints(const PointList& input, const PointList& contracted, int k,
                                           const ThinningParameters& parameters, StageSeconds* seconds = nullptr,
                                           const ProgressCallback& progress = {});

}  // namespace pcskeleton
