#include "pcskeleton/curve_skeleton.h"

#include "pcskeleton/finishing/bone_radii.h"
#include "pcskeleton/finishing/node_recentering.h"
#include "pcskeleton/finishing/gap_bridging.h"
#include "pcskeleton/finishing/skeleton_refinement.h"
#include "pcskeleton/skeleton/skeleton_structure.h"
#include "pcskeleton/contraction/contraction_memory.h"
#include "pcskeleton/internal/stopwatch.h"
#include "pcskeleton/skeleton/skeleton_embedding.h"
#include "pcskeleton/skeleton/sheet_collapse.h"
#include "pcskeleton/skeleton/skeleton_thinning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
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
// points (normalised frame); `start`: where contraction started them (the denoised copy of a
// noisy cloud). Fills result.skeleton, result.quality and the seconds of thinning, embedding
// and finishing.
void thinAndEmbed(const NormalizedCloud& cloud, const PointList& start, const OneRings& rings,
                  const PointList& contracted, const SkeletonGraphParameters& parameters, SkeletonResult& result,
                  const ProgressCallback& progress) {
    checkSkeletonGraphParameters(parameters);
    Stopwatch stage;
    const double radius = parameters.nodeSpacing * cloud.diagonal;
    const double maxLinkLength = parameters.linkLimit > 0 ? parameters.linkLimit * radius
                                                          : std::numeric_limits<double>::infinity();
    // Flat sheets that contraction cannot thin, onto their medial axes first. Whether a sheet
    // is flat is judged where contraction started: noise that denoising took out of a plate
    // would hide its plane (docs/benchmarks.md, "Noisy plates judged where contraction starts").
    PointList collapsed;
    std::optional<SheetCollapseReport> sheets;
    if (parameters.collapseSheets) {
        collapsed = contracted;
        sheets = collapseSheets(start, collapsed, rings, radius);
    }
    const PointList& thinnedPoints = parameters.collapseSheets ? collapsed : contracted;
    const ThinnedGraph thinned = thinContractedPoints(cloud.points, thinnedPoints, rings, radius, maxLinkLength, progress);
    result.seconds.thinning = stage.seconds();

    stage.restart();
    result.skeleton = embedSkeleton(thinned, cloud);
    result.seconds.embedding = stage.seconds();

    stage.restart();
    const double nodeSpacing = radius / cloud.scale;
    const PointList points = inputPoints(cloud);
    // Re-centring first: refinement judges limbs by the nodes' tubes, which on one-sided
    // parts are only right once the nodes are on the axis.
    const DataSupport support(points, nodeSpacing);
    RecenteringReport recentering;
    if (parameters.recentre) recentering = recentreOneSidedNodes(result.skeleton, points, support);
    RefinementReport refinement;
    if (parameters.refine) {
        refinement = refineSkeleton(result.skeleton, points, nodeSpacing, parameters.refinementLimits);
        for (int& node : recentering.nodes) node = refinement.nodeMap[node];
        std::sort(recentering.nodes.begin(), recentering.nodes.end());
        recentering.nodes.erase(std::unique(recentering.nodes.begin(), recentering.nodes.end()), recentering.nodes.end());
    }
    TipExtensionReport extension;
    if (parameters.extendTips) extension = extendTips(result.skeleton, points, nodeSpacing, support);
    // After tip extension: an extended limb ends at the edge of its data, so the bridge spans
    // the gap in the data and nothing more.
    const GapBridgingReport bridging = bridgeGaps(result.skeleton, nodeSpacing, parameters.gapLimit);
    result.quality = assessSkeleton(result.skeleton, cloud, rings, thinnedPoints, nodeSpacing);
    if (!parameters.refine) {
        for (LoopToOpen& loop : contactLoops(result.skeleton, points, parameters.refinementLimits)) {
            result.quality.contactLoops.push_back(std::move(loop.cycle));
        }
        for (LoopToOpen& loop : filledLoops(result.skeleton, points, nodeSpacing, parameters.refinementLimits)) {
            result.quality.filledLoops.push_back(std::move(loop.cycle));
        }
    }
    // Last, once the bones lie where they stay: each is measured across its own direction.
    // After the quality check, whose test for points that did not contract compares their
    // distance with the spread of each node's points, the radius the embedding gives.
    measureBoneRadii(result.skeleton, points, nodeSpacing);
    result.quality.nodesAwayFromData = support.unsupportedNodes(result.skeleton);
    // A re-centred node is off its points' centre by design, not outside the shape.
    std::vector<int>& outside = result.quality.nodesOutside;
    for (int moved : recentering.nodes) outside.erase(std::remove(outside.begin(), outside.end(), moved), outside.end());
    result.quality.sheets = sheets;
    if (parameters.recentre) result.quality.recentering = recentering;
    if (parameters.refine) result.quality.refinement = refinement;
    if (parameters.gapLimit > 0) result.quality.gapBridging = bridging;
    if (parameters.extendTips) result.quality.tipExtension = extension;
    if (result.contraction.stopReason != StopReason::NotStopped) {
        result.quality.contraction = result.contraction.outcome();
    }
    result.seconds.finishing = stage.seconds();
}

}  // namespace

void checkResolutionParameters(const ResolutionParameters& parameters) {
    if (parameters.maxContractedPoints != 0 &&
        parameters.maxContractedPoints < ResolutionParameters::kFewestContractedPoints) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::ContractedPoints, "must be at least " +
                                             std::to_string(ResolutionParameters::kFewestContractedPoints) +
                                             " (full resolution contracts every point)."));
    }
    if (!(parameters.memoryLimit >= 0 && std::isfinite(parameters.memoryLimit))) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::MemoryLimit, "must be 0 (automatic) or a positive number of GB."));
    }
}

void checkSkeletonGraphParameters(const SkeletonGraphParameters& parameters) {
    if (!(parameters.linkLimit >= 0.0 && std::isfinite(parameters.linkLimit))) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::LinkLimit, "must be 0 (every link connects, the paper's rule) or a positive number of node spacings."));
    }
    if (!(parameters.gapLimit >= 0.0 && std::isfinite(parameters.gapLimit))) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::GapLimit, "must be 0 (no bridge, the paper's skeleton) or a positive number of node spacings."));
    }
    if (!(parameters.refinementLimits.minOpening >= 0.0 && std::isfinite(parameters.refinementLimits.minOpening))) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::LoopOpening, "must be 0 (no loop is opened) or a positive number of tube radii."));
    }
    if (!(parameters.refinementLimits.minClearance >= 0.0 && parameters.refinementLimits.minClearance <= 1.0)) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::LoopClearance, "must be a fraction of a bone's radius between 0 and 1."));
    }
    const double gapStretch = parameters.refinementLimits.gapStretch;
    if (!(gapStretch == 0.0 || (gapStretch >= 1.0 && std::isfinite(gapStretch)))) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::GapStretch, "must be 0 (no bone is cut) or at least 1 (a shorter bone is inside the tubes at its "
                                   "ends)."));
    }
    if (!(parameters.refinementLimits.minHole >= 0.0 && std::isfinite(parameters.refinementLimits.minHole))) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::MinHole, "must be 0 (no loop is opened) or a positive number of node spacings."));
    }
    if (!(parameters.nodeSpacing > 0.0 && parameters.nodeSpacing < 1.0)) {
        std::ostringstream requirement;
        requirement << "must be a fraction of the bounding-box diagonal between 0 and 1 (the paper uses 0.02); got "
                    << parameters.nodeSpacing << ".";
        throw InvalidInput(Problem::aboutParameter(Parameter::NodeSpacing, requirement.str()));
    }
}

SkeletonResult skeletonFromContraction(const LaplacianContraction& contraction, const SkeletonGraphParameters& parameters,
                                       const ProgressCallback& progress) {
    SkeletonResult result;
    result.contraction = contraction.result();
    result.seconds.neighbourhoods = contraction.neighbourhoodSeconds();
    for (const IterationReport& r : contraction.history()) result.seconds.contraction += r.seconds;
    thinAndEmbed(contraction.cloud(), contraction.startPositions(), contraction.rings(),
                 contraction.normalizedPositions(), parameters, result, progress);
    return result;
}

ContractionInput::ContractionInput(const PointList& input, const ResolutionParameters& parameters,
                                   const OutlierParameters& outliers, const ProgressCallback& progress)
    : input_(input) {
    refuseWorkLargerThanMemory(input.size(), parameters.maxContractedPoints, parameters.memoryLimit);
    if (parameters.maxContractedPoints == 0 || input.size() <= parameters.maxContractedPoints) return;
    const Stopwatch stopwatch;
    // The grid needs finite coordinates; the contraction would refuse these anyway.
    rejectNonFinite(input, "input points", Remedy::take(Step::RemoveNonFinitePoints));
    rejectUnrepresentableScale(input, "input points");
    checkOutlierParameters(outliers);
    report(progress, 0, "Multi-resolution: outliers of the whole cloud");
    // The outlier test and the grid see each position once (a point repeated more often than
    // the test has neighbours would be alone with its copies); each copy then follows its
    // position's keeper.
    const ExactDuplicates duplicates = findExactDuplicates(input);
    const PointList distinct = duplicates.any() ? distinctPoints(input, duplicates) : PointList{};
    const PointList& positions = duplicates.any() ? distinct : input;
    const std::vector<char> outlier = findOutliers(positions, outliers);
    report(progress, 80, "Multi-resolution: subsample");
    subsample_ = spreadSubsample(positions, parameters.maxContractedPoints, outlier);
    kept_ = keptPoints(positions, subsample_);
    if (duplicates.any()) {
        for (int& kept : subsample_.kept) kept = duplicates.firstOf[std::size_t(kept)];
        std::vector<int> keeperOf(input.size());
        for (std::size_t i = 0; i < input.size(); ++i) {
            const std::size_t group = std::size_t(duplicates.groupOf[i]);
            keeperOf[i] = subsample_.keeperOf[group];
            outliers_ += outlier[group];
        }
        subsample_.keeperOf = std::move(keeperOf);
    } else {
        outliers_ = std::size_t(std::count(outlier.begin(), outlier.end(), 1));
    }
    subsampled_ = true;
    report(progress, 100, "Multi-resolution: subsample taken");
    seconds_ = stopwatch.seconds();
}

void ContractionInput::carryToAllPoints(SkeletonResult& result) const {
    if (!subsampled_) return;
    const Stopwatch stopwatch;
    SkeletonGraph& skeleton = result.skeleton;
    const std::vector<int> keptNode = std::move(skeleton.pointNode);
    skeleton.pointNode.resize(input_.size());
    for (std::size_t i = 0; i < input_.size(); ++i) {
        const int keeper = subsample_.keeperOf[i];
        skeleton.pointNode[i] = keeper < 0 ? -1 : keptNode[keeper];
    }
    // Radii from every point, as the embedding and the finishing measure them; a node
    // without points (or with only one, at its own place) keeps the radius it has.
    const std::vector<double> radius = meanDistanceToNodes(input_, skeleton.pointNode, skeleton.nodes);
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
        if (radius[n] > 0) skeleton.radii[n] = radius[n];
    }
    measureBoneRadii(skeleton, input_, result.quality.nodeSpacing);
    PointList& contracted = result.contraction.contracted;
    if (!contracted.empty()) {
        const PointList keptContracted = std::move(contracted);
        contracted.resize(input_.size());
        for (std::size_t i = 0; i < input_.size(); ++i) {
            const int keeper = subsample_.keeperOf[i];
            contracted[i] = keeper < 0 ? input_[i] : keptContracted[keeper];  // an outlier stays, as in the contraction
        }
    }
    result.quality.inputPoints = input_.size();
    result.quality.inputOutliers = outliers_;
    result.seconds.subsampling = seconds_ + stopwatch.seconds();
    result.quality.subsampleCellSize = subsample_.cellSize;
}

SkeletonPipeline::SkeletonPipeline(const PointList& input, const SkeletonParameters& parameters,
                                   const ProgressCallback& progress)
    : parameters_((checkContractionParameters(parameters.contraction), checkSkeletonGraphParameters(parameters.graph),
                   checkResolutionParameters(parameters.resolution), parameters)),
      input_(input, parameters.resolution, parameters.contraction.outliers, progressRange(progress, 0, 40)),
      contraction_(input_.points(), parameters.contraction, progressRange(progress, 40, 100)) {}

SkeletonResult SkeletonPipeline::skeleton(const ProgressCallback& progress) const {
    return skeleton(parameters_.graph, progress);
}

SkeletonResult SkeletonPipeline::skeleton(const SkeletonGraphParameters& graph, const ProgressCallback& progress) const {
    checkSkeletonGraphParameters(graph);
    SkeletonResult result = skeletonFromContraction(contraction_, graph, progress);
    input_.carryToAllPoints(result);
    return result;
}

SkeletonResult computeCurveSkeleton(const PointList& input, const SkeletonParameters& parameters,
                                    const ProgressCallback& progress) {
    SkeletonPipeline pipeline(input, parameters, progressRange(progress, 0, 25));
    pipeline.contraction().iterateToEnd(progressRange(progress, 25, 90));
    return pipeline.skeleton(progressRange(progress, 90, 100));
}

namespace {

void requireOneContractedPointPerInputPoint(const PointList& input, const PointList& contracted) {
    if (contracted.size() != input.size()) {
        std::ostringstream message;
        message << "There are " << contracted.size() << " contracted points for " << input.size()
                << " input points: the contracted points must be those made from this input, one per point.";
        throw InvalidInput(message.str(), {Remedy::take(Step::ContractAgain)});
    }
}

}  // namespace

SkeletonResult skeletonFromContractedPoints(const PointList& input, const PointList& contracted,
                                            const SkeletonParameters& parameters, const ProgressCallback& progress) {
    requireOneContractedPointPerInputPoint(input, contracted);
    checkContractionParameters(parameters.contraction);
    checkSkeletonGraphParameters(parameters.graph);
    checkResolutionParameters(parameters.resolution);
    const ContractionInput work(input, parameters.resolution, parameters.contraction.outliers,
                                progressRange(progress, 0, 30));
    if (!work.subsampled()) {
        return skeletonFromContractedPoints(input, contracted, parameters.contraction, parameters.graph,
                                            progressRange(progress, 30, 100));
    }
    // Thinning checks the subsample's points; the others are checked here, so that a damaged
    // file is refused whole rather than half read.
    rejectNonFinite(contracted, "contracted points", Remedy::take(Step::ContractAgain));
    PointList keptContracted;
    keptContracted.reserve(work.subsample().kept.size());
    for (int kept : work.subsample().kept) keptContracted.push_back(contracted[std::size_t(kept)]);
    SkeletonResult result = skeletonFromContractedPoints(work.points(), keptContracted, parameters.contraction,
                                                         parameters.graph, progressRange(progress, 30, 100));
    work.carryToAllPoints(result);
    return result;
}

SkeletonResult skeletonFromContractedPoints(const PointList& input, const PointList& contracted,
                                            const ContractionParameters& contraction,
                                            const SkeletonGraphParameters& parameters, const ProgressCallback& progress) {
    requireOneContractedPointPerInputPoint(input, contracted);
    // The same cloud and 1-rings as the contraction's.
    const ContractionStart start = prepareContraction(input, contraction, progressRange(progress, 0, 50));
    const NormalizedCloud& cloud = start.cloud;
    SkeletonResult result;
    result.contraction.denoisingPasses = start.denoising.passes;
    result.contraction.surfaceNoise = start.denoising.surfaceNoise;
    result.contraction.facingNeighboursLeftOut = facingNeighboursLeftOut(contraction, start.rings);
    result.seconds.neighbourhoods = start.neighbourhoodSeconds;

    rejectNonFinite(contracted, "contracted points", Remedy::take(Step::ContractAgain));
    PointList contractedUnique(cloud.points.size());
    for (std::size_t i = 0; i < input.size(); ++i) {
        if (!cloud.isOutlier(i)) contractedUnique[cloud.uniqueIndex[i]] = cloud.toNormalizedFrame(contracted[i]);
    }
    result.contraction.contracted = contracted;
    thinAndEmbed(cloud, start.positions, start.rings, contractedUnique, parameters, result,
                 progressRange(progress, 50, 100));
    return result;
}

}  // namespace pcskeleton
