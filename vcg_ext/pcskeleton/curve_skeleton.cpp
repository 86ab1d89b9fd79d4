#include "pcskeleton/curve_skeleton.h"

#include "pcskeleton/skeleton/skeleton_embedding.h"
#include "pcskeleton/analysis/skeleton_refinement.h"
#include "pcskeleton/skeleton/skeleton_thinning.h"

#include <chrono>
#include <sstream>

namespace pcskeleton {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The input points in the input's frame and order (duplicates merged by the cloud keep
// their common position).
PointList inputPoints(const NormalizedCloud& cloud) {
    PointList points;
    points.reserve(cloud.inputSize());
    for (int unique : cloud.uniqueIndex) points.push_back(cloud.toInputFrame(cloud.points[unique]));
    return points;
}

// Steps 4-5, refinement, tip extension and quality on contracted positions of the distinct
// points (normalised frame). Fills result.skeleton, result.quality and the seconds of
// thinning, embedding and finishing.
void thinAndEmbed(const NormalizedCloud& cloud, const OneRings& rings, const PointList& contracted,
                  const ThinningParameters& parameters, SkeletonResult& result, const ProgressCallback& progress) {
    checkThinningParameters(parameters);
    auto start = std::chrono::steady_clock::now();
    const double radius = parameters.sampleRadius * cloud.diagonal;
    const ThinnedGraph thinned = thinContractedPoints(contracted, rings, radius, progress);
    result.seconds.thinning = secondsSince(start);

    start = std::chrono::steady_clock::now();
    result.skeleton = embedSkeleton(thinned, cloud);
    result.seconds.embedding = secondsSince(start);

    start = std::chrono::steady_clock::now();
    const double nodeSpacing = radius / cloud.scale;
    RefinementReport refinement;
    if (parameters.refine) refinement = refineSkeleton(result.skeleton, nodeSpacing);
    TipExtensionReport extension;
    if (parameters.extendTips) extension = extendTips(result.skeleton, inputPoints(cloud), nodeSpacing);
    result.quality = assessSkeleton(result.skeleton, cloud, rings, contracted, nodeSpacing);
    result.quality.refined = parameters.refine;
    result.quality.refinement = refinement;
    result.quality.tipsExtended = parameters.extendTips;
    result.quality.tipExtension = extension;
    const ContractionResult& c = result.contraction;
    result.quality.stopReason = c.stopReason;
    result.quality.iterations = int(c.iterations.size());
    result.quality.extentRatio = c.iterations.empty() ? 1.0 : c.iterations.back().extentRatio;
    result.seconds.finishing = secondsSince(start);
}

}  // namespace

void checkThinningParameters(const ThinningParameters& parameters) {
    if (!(parameters.sampleRadius > 0.0 && parameters.sampleRadius < 1.0)) {
        std::ostringstream message;
        message << "The sampling radius must be a fraction of the bounding-box diagonal between 0 and 1 "
                << "(the paper uses 0.02); got " << parameters.sampleRadius << ".";
        throw InvalidInput(message.str());
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

SkeletonResult skeletonFromContractedPoints(const PointList& input, const PointList& contracted, int k,
                                            const ThinningParameters& parameters, const ProgressCallback& progress) {
    if (contracted.size() != input.size()) {
        std::ostringstream message;
        message << "The contracted layer has " << contracted.size() << " points but its input has " << input.size()
                << "; contract that input again.";
        throw InvalidInput(message.str());
    }
    const int neighbours = k > 0 ? k : defaultNeighbourCount(input.size());
    const NormalizedCloud cloud = normalizeCloud(input, std::size_t(neighbours) + 1);
    SkeletonResult result;
    auto start = std::chrono::steady_clock::now();
    const OneRings rings = OneRings::compute(cloud.points, neighbours, progressRange(progress, 0, 50));
    result.seconds.neighbourhoods = secondsSince(start);

    rejectNonFinite(contracted, "contracted points", "Contract the input again.");
    PointList contractedUnique(cloud.points.size());
    for (std::size_t i = 0; i < input.size(); ++i) contractedUnique[cloud.uniqueIndex[i]] = cloud.toNormalizedFrame(contracted[i]);
    result.contraction.contracted = contracted;
    thinAndEmbed(cloud, rings, contractedUnique, parameters, result, progressRange(progress, 50, 100));
    return result;
}

}  // namespace pcskeleton
