#include "pcskeleton/curve_skeleton.h"

#include "pcskeleton/skeleton_embedding.h"
#include "pcskeleton/skeleton_thinning.h"

#include <chrono>
#include <sstream>

namespace pcskeleton {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Steps 4-5 on contracted positions of the distinct points (normalised frame).
SkeletonGraph thinAndEmbed(const NormalizedCloud& cloud, const OneRings& rings, const PointList& contracted,
                           const ThinningParameters& parameters, StageSeconds* seconds,
                           const ProgressCallback& progress) {
    checkThinningParameters(parameters);
    auto start = std::chrono::steady_clock::now();
    const double radius = parameters.sampleRadius * cloud.diagonal;
    const ThinnedGraph thinned = thinContractedPoints(contracted, rings, radius, progress);
    if (seconds) seconds->thinning = secondsSince(start);
    start = std::chrono::steady_clock::now();
    SkeletonGraph skeleton = embedSkeleton(thinned, cloud);
    if (seconds) seconds->embedding = secondsSince(start);
    return skeleton;
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

SkeletonGraph skeletonFromContraction(const LaplacianContraction& contraction, const ThinningParameters& parameters,
                                      StageSeconds* seconds, const ProgressCallback& progress) {
    if (seconds) {
        seconds->neighbourhoods = contraction.neighbourhoodSeconds();
        seconds->contraction = 0;
        for (const IterationReport& r : contraction.history()) seconds->contraction += r.seconds;
    }
    return thinAndEmbed(contraction.cloud(), contraction.rings(), contraction.normalizedPositions(), parameters,
                        seconds, progress);
}

SkeletonResult computeCurveSkeleton(const PointList& input, const SkeletonParameters& parameters,
                                    const ProgressCallback& progress) {
    checkThinningParameters(parameters.thinning);
    SkeletonResult result;
    LaplacianContraction contraction(input, parameters.contraction, progressRange(progress, 0, 25));
    contraction.iterateToEnd(progressRange(progress, 25, 90));
    result.contraction = contraction.result();
    result.skeleton =
        skeletonFromContraction(contraction, parameters.thinning, &result.seconds, progressRange(progress, 90, 100));
    return result;
}

SkeletonGraph skeletonFromContractedPoints(const PointList& input, const PointList& contracted, int k,
                                           const ThinningParameters& parameters, StageSeconds* seconds,
                                           const ProgressCallback& progress) {
    if (contracted.size() != input.size()) {
        std::ostringstream message;
        message << "The contracted layer has " << contracted.size() << " points but its input has " << input.size()
                << "; contract that input again.";
        throw InvalidInput(message.str());
    }
    const int neighbours = k > 0 ? k : defaultNeighbourCount(input.size());
    const NormalizedCloud cloud = normalizeCloud(input, std::size_t(neighbours) + 1);
    auto start = std::chrono::steady_clock::now();
    const OneRings rings = OneRings::compute(cloud.points, neighbours, progressRange(progress, 0, 50));
    if (seconds) seconds->neighbourhoods = secondsSince(start);

    rejectNonFinite(contracted, "contracted points", "Contract the input again.");
    PointList contractedUnique(cloud.points.size());
    for (std::size_t i = 0; i < input.size(); ++i) contractedUnique[cloud.uniqueIndex[i]] = cloud.toNormalizedFrame(contracted[i]);
    return thinAndEmbed(cloud, rings, contractedUnique, parameters, seconds, progressRange(progress, 50, 100));
}

}  // namespace pcskeleton
