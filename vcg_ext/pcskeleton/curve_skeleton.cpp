#include "pcskeleton/curve_skeleton.h"

#include "pcskeleton/analysis/node_recentering.h"
#include "pcskeleton/analysis/skeleton_refinement.h"
#include "pcskeleton/internal/stopwatch.h"
#include "pcskeleton/skeleton/skeleton_embedding.h"
#include "pcskeleton/skeleton/skeleton_thinning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace pcskeleton {

namespace {


// The input points in the input's frame and order (duplicates merged by the cloud keep
// their common position).
PointList inputPoints(const NormalizedCloud& cloud) {
    PointList points;
    points.reserve(cloud.inputSize());
    for (std::size_t i = 0; i < cloud.inputSize(); ++i) points.push_back(cloud.inputPosition(i));
    return points;
}

// Steps 4-5, refinement, tip extension and quality on contracted positions of the distinct
// points (normalised frame). Fills result.skeleton, result.quality and the seconds of
// thinning, embedding and finishing.
void thinAndEmbed(const NormalizedCloud& cloud, const OneRings& rings, const PointList& contracted,
                  const ThinningParameters& parameters, SkeletonResult& result, const ProgressCallback& progress) {
    checkThinningParameters(parameters);
    Stopwatch stage;
    const double radius = parameters.sampleRadius * cloud.diagonal;
    const double maxLinkLength = parameters.linkLimit > 0 ? parameters.linkLimit * radius
                                                          : std::numeric_limits<double>::infinity();
    const ThinnedGraph thinned = thinContractedPoints(cloud.points, contracted, rings, radius, maxLinkLength, progress);
    result.seconds.thinning = stage.seconds();

    stage.restart();
    result.skeleton = embedSkeleton(thinned, cloud);
    result.seconds.embedding = stage.seconds();

    stage.restart();
    const double nodeSpacing = radius / cloud.scale;
    const PointList points = inputPoints(cloud);
    // Re-centring first: refinement judges limbs by the nodes' tubes, which on one-sided
    // parts are only right once the nodes are on the axis (bench_robustness: the ring
    // scanned from one view loses its spur).
    RecenteringReport recentering;
    if (parameters.recentre) recentering = recentreOneSidedNodes(result.skeleton, points);
    RefinementReport refinement;
    if (parameters.refine) {
        refinement = refineSkeleton(result.skeleton, points, nodeSpacing);
        for (int& node : recentering.nodes) node = refinement.nodeMap[node];
        std::sort(recentering.nodes.begin(), recentering.nodes.end());
        recentering.nodes.erase(std::unique(recentering.nodes.begin(), recentering.nodes.end()), recentering.nodes.end());
    }
    TipExtensionReport extension;
    if (parameters.extendTips) extension = extendTips(result.skeleton, points, nodeSpacing);
    result.quality = assessSkeleton(result.skeleton, cloud, rings, contracted, nodeSpacing);
    // A re-centred node is off its points' centre by design, not outside the shape.
    std::vector<int>& outside = result.quality.nodesOutside;
    for (int moved : recentering.nodes) outside.erase(std::remove(outside.begin(), outside.end(), moved), outside.end());
    result.quality.recentred = parameters.recentre;
    result.quality.recentering = recentering;
    result.quality.refined = parameters.refine;
    result.quality.refinement = refinement;
    result.quality.tipsExtended = parameters.extendTips;
    result.quality.tipExtension = extension;
    const ContractionResult& c = result.contraction;
    result.quality.stopReason = c.stopReason;
    result.quality.iterations = int(c.iterations.size());
    result.quality.extentRatio = c.iterations.empty() ? 1.0 : c.iterations.back().extentRatio;
    result.quality.denoisingPasses = c.denoisingPasses;
    result.quality.surfaceNoise = c.surfaceNoise;
    result.seconds.finishing = stage.seconds();
}

}  // namespace

void checkThinningParameters(const ThinningParameters& parameters) {
    if (!(parameters.linkLimit >= 0.0 && std::isfinite(parameters.linkLimit))) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::LinkLimit, "must be 0 (every link connects, the paper's rule) or a positive number of node spacings."));
    }
    if (!(parameters.sampleRadius > 0.0 && parameters.sampleRadius < 1.0)) {
        std::ostringstream requirement;
        requirement << "must be a fraction of the bounding-box diagonal between 0 and 1 (the paper uses 0.02); got "
                    << parameters.sampleRadius << ".";
        throw InvalidInput(Problem::aboutParameter(Parameter::NodeSpacing, requirement.str()));
    }
}

SkeletonResult skeletonFromContraction(const LaplacianContraction& contraction, const ThinningParameters& parameters,
                                       const ProgressCallback& progress) {
    SkeletonResult result;
    result.contraction = contraction.result();
    result.seconds.neighbourhoods = contraction.neighbourhoodSeconds();
    for (const IterationReport& r : contraction.history()) result.seconds.contraction += r.seconds;
    thinAndEmbed(contraction.cloud(), contraction.rings(), contraction.normalizedPositions(), parameters, result,
                 progress);
    return result;
}

SkeletonResult computeCurveSkeleton(const PointList& input, const SkeletonParameters& parameters,
                                    const ProgressCallback& progress) {
    checkThinningParameters(parameters.thinning);
    LaplacianContraction contraction(input, parameters.contraction, progressRange(progress, 0, 25));
    contraction.iterateToEnd(progressRange(progress, 25, 90));
    return skeletonFromContraction(contraction, parameters.thinning, progressRange(progress, 90, 100));
}

SkeletonResult skeletonFromContractedPoints(const PointList& input, const PointList& contracted,
                                            const ContractionParameters& contraction,
                                            const ThinningParameters& parameters, const ProgressCallback& progress) {
    if (contracted.size() != input.size()) {
        std::ostringstream message;
        message << "The contracted layer has " << contracted.size() << " points but its input has " << input.size()
                << ".";
        throw InvalidInput(message.str(), {Remedy::take(Step::ContractAgain)});
    }
    // The same cloud and 1-rings as the contraction's.
    const ContractionStart start = prepareContraction(input, contraction, progressRange(progress, 0, 50));
    const NormalizedCloud& cloud = start.cloud;
    SkeletonResult result;
    result.contraction.denoisingPasses = start.denoising.passes;
    result.contraction.surfaceNoise = start.denoising.surfaceNoise;
    result.seconds.neighbourhoods = start.neighbourhoodSeconds;

    rejectNonFinite(contracted, "contracted points", Remedy::take(Step::ContractAgain));
    PointList contractedUnique(cloud.points.size());
    for (std::size_t i = 0; i < input.size(); ++i) {
        if (!cloud.isOutlier(i)) contractedUnique[cloud.uniqueIndex[i]] = cloud.toNormalizedFrame(contracted[i]);
    }
    result.contraction.contracted = contracted;
    thinAndEmbed(cloud, start.rings, contractedUnique, parameters, result, progressRange(progress, 50, 100));
    return result;
}

}  // namespace pcskeleton
