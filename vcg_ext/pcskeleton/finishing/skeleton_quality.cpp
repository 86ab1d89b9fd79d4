#include "pcskeleton/finishing/skeleton_quality.h"

#include "pcskeleton/internal/counted.h"
#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/skeleton/skeleton_distance.h"
#include "pcskeleton/skeleton/skeleton_structure.h"

#include <iomanip>
#include <sstream>

namespace pcskeleton {

namespace {

constexpr double kUncontractedRadiusShare = 1.0;
constexpr double kUncontractedShareWarning = 0.01;
// More than this share set aside suggests real data taken for outliers: uniform outliers
// are found only in part (docs/benchmarks.md#measurements-behind-the-constants).
constexpr double kOutlierShareWarning = 0.05;
constexpr double kOneSidedness = 0.8;
constexpr int kMinimumPointsForSideCheck = 4;

// "; 2 moves refused (they would have taken a node away from its data)", or nothing.
std::string refusals(int count, const char* what) {
    if (count == 0) return "";
    return "; " + counted(std::size_t(count), std::string(what)) +
           " refused (" + (count == 1 ? "it" : "they") + " would have taken a node away from its data)";
}

std::string percent(double share) {
    std::ostringstream s;
    s << std::setprecision(share < 0.1 ? 2 : 3) << 100.0 * share << "%";
    return s.str();
}

// Points whose contracted position is no closer to the skeleton than the surface is:
// farther from the nearest bone than the radius there (docs/benchmarks.md#measurements-behind-the-constants).
std::size_t countUncontracted(const SkeletonGraph& skeleton, const NormalizedCloud& cloud, const PointList& contracted) {
    if (skeleton.nodeCount() == 0) return cloud.inputSize() - cloud.outliers.size();
    const SkeletonDistance distance(skeleton);
    std::vector<char> stayed(contracted.size(), 0);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < long(contracted.size()); ++i) {
        const SkeletonProximity near = distance.nearest(cloud.toInputFrame(contracted[i]));
        stayed[i] = near.distance > kUncontractedRadiusShare * near.radius;
    }
    std::size_t uncontracted = 0;
    for (int unique : cloud.uniqueIndex) uncontracted += unique >= 0 && stayed[unique];
    return uncontracted;
}

void checkInputParts(const SkeletonGraph& skeleton, const NormalizedCloud& cloud, const OneRings& rings,
                     SkeletonQuality& quality) {
    DisjointSets parts(cloud.points.size());
    for (std::size_t i = 0; i < cloud.points.size(); ++i) {
        for (const int* j = rings.ringBegin(i); j != rings.ringEnd(i); ++j) parts.unite(int(i), *j);
    }
    const std::vector<int> degree = nodeDegrees(skeleton.nodeCount(), skeleton.edges);
    std::vector<char> isPart(cloud.points.size(), 0), hasBone(cloud.points.size(), 0);
    std::vector<std::size_t> partPoints(cloud.points.size(), 0);
    for (std::size_t i = 0; i < cloud.inputSize(); ++i) {
        if (cloud.isOutlier(i)) continue;
        const int part = parts.find(cloud.uniqueIndex[i]);
        const int node = skeleton.pointNode[i];
        isPart[part] = 1;
        ++partPoints[part];
        if (node >= 0 && degree[node] > 0) hasBone[part] = 1;
        if (node >= 0 && degree[node] == 0) ++quality.pointsOfIsolatedNodes;
    }
    for (std::size_t p = 0; p < isPart.size(); ++p) {
        if (!isPart[p]) continue;
        ++quality.inputParts;
        if (!hasBone[p]) ++quality.partsWithoutBone, quality.pointsWithoutBone += partPoints[p];
    }
}

std::vector<int> nodesWithPointsOnOneSide(const SkeletonGraph& skeleton, const NormalizedCloud& cloud) {
    std::vector<Point> directionSum(skeleton.nodeCount(), Point::Zero());
    std::vector<int> members(skeleton.nodeCount(), 0);
    for (std::size_t i = 0; i < cloud.inputSize(); ++i) {
        const int node = skeleton.pointNode[i];
        if (node < 0) continue;
        const Point toPoint = cloud.toInputFrame(cloud.points[cloud.uniqueIndex[i]]) - skeleton.nodes[node];
        const double distance = toPoint.norm();
        if (distance > 0.0) directionSum[node] += toPoint / distance, ++members[node];
    }
    std::vector<int> outside;
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
        if (members[n] >= kMinimumPointsForSideCheck && directionSum[n].norm() > kOneSidedness * members[n]) {
            outside.push_back(int(n));
        }
    }
    return outside;
}

}  // namespace

SkeletonQuality assessSkeleton(const SkeletonGraph& skeleton, const NormalizedCloud& cloud, const OneRings& rings,
                               const PointList& contracted, double nodeSpacing) {
    SkeletonQuality quality;
    quality.topology = analyseTopology(skeleton);
    quality.nodeSpacing = nodeSpacing;
    quality.points = cloud.inputSize();
    quality.inputPoints = cloud.inputSize();
    quality.outliers = cloud.outliers.size();
    quality.uncontractedPoints = countUncontracted(skeleton, cloud, contracted);
    checkInputParts(skeleton, cloud, rings, quality);
    quality.nodesOutside = nodesWithPointsOnOneSide(skeleton, cloud);
    for (const Limb& limb : tipLimbs(skeleton)) {
        if (isSpur(skeleton, limb, nodeSpacing)) quality.spurs.push_back(limb.path);
    }
    for (std::vector<int>& cycle : shortCycleBasis(skeleton)) {
        if (isSpuriousCycle(skeleton, cycle, nodeSpacing)) quality.spuriousCycles.push_back(std::move(cycle));
    }
    return quality;
}

std::vector<QualityWarning> SkeletonQuality::warnings() const {
    using Kind = QualityWarning::Kind;
    std::vector<QualityWarning> w;
    const auto add = [&w](Kind kind, std::string description, std::vector<Remedy> remedies) {
        w.push_back({kind, Problem{std::move(description), std::move(remedies)}});
    };
    const StopReason stopReason = contraction ? contraction->stopReason : StopReason::NotStopped;
    if (stopReason == StopReason::IterationLimit) {
        add(Kind::IterationLimit, "Contraction stopped at the iteration limit before converging",
            {Remedy::raise(Parameter::MaxIterations), Remedy::raise(Parameter::ContractionScale)});
    } else if (stopReason == StopReason::NumericalFailure) {
        add(Kind::NumericalFailure, "Contraction failed numerically and kept its last good positions",
            {Remedy::lower(Parameter::InitialContractionWeight), Remedy::lower(Parameter::LaplacianRowLimit)});
    }
    if (points > 0 && outliers > kOutlierShareWarning * points) {
        add(Kind::ManyOutliers,
            counted(outliers, "point", "points") + " (" + percent(double(outliers) / points) +
                ") were set aside as outliers: if some are a sparsely sampled part of the shape, it is missing from "
                "the skeleton.",
            {Remedy::raise(Parameter::OutlierIsolation), Remedy::raise(Parameter::OutlierLocalFactor),
             Remedy::turnOff(Parameter::OutlierDetection)});
    }
    if (points > 0 && uncontractedPoints > kUncontractedShareWarning * points) {
        // Converged: further iterations leave these points where they are (the rings of the
        // parts already on a curve grow back, which is what stops it). A slower growth of W_L
        // is the paper's answer to thick parts next to thin ones (its Sec. VI).
        const bool converged = stopReason == StopReason::Converged;
        add(Kind::UncontractedPoints,
            counted(uncontractedPoints, "point", "points") + " (" + percent(double(uncontractedPoints) / points) +
                ") did not contract (they stayed farther from the skeleton than its radius there): outliers, or a "
                "part " +
                (converged ? "that contraction does not thin (a flat plate or disc, a body much thicker than its "
                             "limbs); it converged, so more iterations would not move them."
                           : "too flat or thick for the iterations given."),
            converged ? std::vector<Remedy>{Remedy::take(Step::RemoveOutliers), Remedy::lower(Parameter::ContractionScale),
                                            Remedy::raise(Parameter::NeighbourCount)}
                      : std::vector<Remedy>{Remedy::take(Step::RemoveOutliers), Remedy::raise(Parameter::NeighbourCount),
                                            Remedy::raise(Parameter::MaxIterations)});
    }
    if (partsWithoutBone > 0) {
        add(Kind::PartsWithoutBone,
            counted(partsWithoutBone, "part", "parts") + " of the input (" +
                counted(pointsWithoutBone, "point", "points") +
                ") gave no bone: each collapsed to an isolated node (outlier clusters, or blob-like pieces "
                "separate from the rest, or real parts cut off).",
            {Remedy::take(Step::RemoveOutliers), Remedy::lower(Parameter::NeighbourCount)});
    }
    if (topology.isolated > 0) {
        add(Kind::IsolatedNodes,
            counted(std::size_t(topology.isolated), "node has", "nodes have") + " no bone (" +
                counted(pointsOfIsolatedNodes, "point", "points") + "): outliers, or pieces too small to give a curve.",
            {Remedy::take(Step::RemoveOutliers), Remedy::take(Step::DeleteNodes)});
    }
    if (!nodesOutside.empty()) {
        add(Kind::NodesOutside,
            counted(nodesOutside.size(), "node lies", "nodes lie") +
                " outside the shape (all its points on one side), e.g. where the centre of a bent part falls "
                "outside it",
            {Remedy::lower(Parameter::NodeSpacing)});
    }
    if (!nodesAwayFromData.empty()) {
        add(Kind::NodesAwayFromData,
            counted(nodesAwayFromData.size(), "node lies away from its data", "nodes lie away from their data") +
                " (first: node " +
                std::to_string(nodesAwayFromData.front()) +
                "), farther from its nearest point than its radius allows or outside the points' bounding box",
            {Remedy::turnOff(Parameter::Recentre), Remedy::take(Step::DeleteNodes)});
    }
    if (!spurs.empty()) {
        add(Kind::Spurs,
            counted(spurs.size(), "short spur", "short spurs") +
                " (limbs shorter than the body is thick where they join): usually noise.",
            {Remedy::turnOn(Parameter::Refinement), Remedy::take(Step::DeleteNodes),
             Remedy::raise(Parameter::NeighbourCount)});
    }
    if (!spuriousCycles.empty()) {
        add(Kind::SpuriousCycles,
            counted(spuriousCycles.size(), "loop is", "loops are") +
                " smaller than the tube around them (no hole to go round): probably spurious.",
            {Remedy::turnOn(Parameter::Refinement), Remedy::raise(Parameter::NodeSpacing),
             Remedy::take(Step::MergeNodes)});
    }
    if (!contactLoops.empty()) {
        add(Kind::ContactLoops,
            counted(contactLoops.size(), "loop is", "loops are") +
                " narrower than the tube around them and closed by a bone that crosses the surface: "
                "probably two parts that touch, or noise across a narrow gap.",
            {Remedy::turnOn(Parameter::Refinement), Remedy::take(Step::DeleteNodes)});
    }
    if (!filledLoops.empty()) {
        add(Kind::FilledLoops,
            counted(filledLoops.size(), "loop goes", "loops go") +
                " round points rather than a hole (their points cover the inside, or a limb lies across it): "
                "probably a one-view scan of a rounded part or of a limb in front of the body, or a limb touching "
                "the body.",
            {Remedy::turnOn(Parameter::Refinement), Remedy::take(Step::DeleteNodes)});
    }
    return w;
}

std::string describeFindings(const SkeletonQuality& q) {
    std::ostringstream s;
    s << "Skeleton: " << describe(q.topology) << "; node spacing " << std::setprecision(3) << q.nodeSpacing << ".\n";
    const ContractionOutcome contraction = q.contraction.value_or(ContractionOutcome{});
    if (!q.contraction) {
        s << "Contraction: thinned from saved contracted points.\n";
    } else {
        s << "Contraction: " << counted(std::size_t(contraction.iterations), "iteration", "iterations") << ", "
          << describe(contraction.stopReason) << "; mean 1-ring size " << percent(contraction.extentRatio)
          << " of the initial.\n";
    }
    s << "Denoising: ";
    if (contraction.denoisingPasses == 0) s << "none";
    else s << counted(std::size_t(contraction.denoisingPasses), "pass", "passes") << " on the contracted copy";
    if (contraction.surfaceNoise >= 0) {
        s << " (automatic: surface noise " << std::setprecision(2) << contraction.surfaceNoise
          << (contraction.denoisingPasses > 0 ? ", a noisy cloud)" : ", a clean cloud)");
    }
    s << ".\n";
    if (q.contraction) {
        s << "Facing walls: ";
        if (contraction.facingNeighboursLeftOut < 0) s << "off.\n";
        else s << counted(std::size_t(contraction.facingNeighboursLeftOut), "neighbour", "neighbours")
               << " across a gap left out of the 1-rings (on another part's wall, facing the point's own).\n";
    }
    if (q.contraction && contraction.medialPullPoints >= 0) {
        s << "Medial pull: " << counted(std::size_t(contraction.medialPullPoints), "point", "points")
          << " pulled towards their medial centre (the others' inside is open).\n";
    }
    if (q.inputPoints > q.points) {
        s << "Input: " << counted(q.inputPoints, "point", "points") << ", " << counted(q.inputOutliers, "outlier", "outliers")
          << " set aside (no node); multi-resolution: " << q.points << " contracted";
        if (q.subsampleCellSize > 0) {
            s << ", one per cube of side " << std::setprecision(3) << q.subsampleCellSize
              << ", the others take their cube's node";
        } else {
            s << " (all but the outliers: few enough)";
        }
        s << ". Of the contracted: "
          << counted(std::size_t(q.inputParts), "part", "parts") << "; ";
    } else {
        s << "Input: " << counted(q.points, "point", "points") << " in "
          << counted(std::size_t(q.inputParts), "part", "parts") << "; ";
    }
    s << counted(q.outliers, "outlier", "outliers") << " set aside (no node); " << q.uncontractedPoints
      << " did not contract.\n";
    s << "Sheets: ";
    if (!q.sheets) s << "off.\n";
    else if (q.sheets->patches == 0) s << "none wide and flat enough to be moved onto their medial axes.\n";
    else s << counted(std::size_t(q.sheets->patches), "flat patch", "flat patches") << " ("
           << counted(q.sheets->points, "point", "points") << ") moved onto "
           << (q.sheets->patches == 1 ? "its medial axis" : "their medial axes") << " before thinning.\n";
    s << "Tip extension: ";
    if (!q.tipExtension) s << "off.\n";
    else if (q.tipExtension->extendedTips == 0) s << "no limb to extend.\n";
    else s << counted(std::size_t(q.tipExtension->extendedTips), "limb", "limbs") << " extended, by "
           << std::setprecision(3) << q.tipExtension->meanLength << " on average, at most "
           << q.tipExtension->longest << refusals(q.tipExtension->refused, "extension") << ".\n";
    s << "Re-centring: ";
    if (!q.recentering) s << "off.\n";
    else {
        s << counted(std::size_t(q.recentering->recentredNodes), "node", "nodes") << " of one-sided parts moved";
        if (q.recentering->recentredNodes) s << ", by " << std::setprecision(3) << q.recentering->meanShift << " on average";
        if (q.recentering->unlikeNeighbours)
            s << "; " << counted(std::size_t(q.recentering->unlikeNeighbours), "node", "nodes")
              << " left in place (curled like a leaf: no neighbour shows the same tube)";
        if (q.recentering->foldedSheets)
            s << "; " << counted(std::size_t(q.recentering->foldedSheets), "node", "nodes")
              << " left in place (folded like a leaf: the points across the bone do not curve evenly)";
        s << refusals(q.recentering->refused, "move") << ".\n";
    }
    s << "Refinement: " << (q.refinement ? describe(*q.refinement) : std::string("off")) << ".\n";
    s << "Gaps in the data: " << (q.gapBridging ? describe(*q.gapBridging) : std::string("off")) << ".";
    return s.str();
}

std::string describe(const SkeletonQuality& q, const Terms& terms) {
    std::string text = describeFindings(q);
    const std::vector<QualityWarning> warnings = q.warnings();
    if (warnings.empty()) text += "\nNo warnings.";
    for (const QualityWarning& w : warnings) text += "\nWarning: " + describe(w.problem, terms);
    return text;
}

}  // namespace pcskeleton
