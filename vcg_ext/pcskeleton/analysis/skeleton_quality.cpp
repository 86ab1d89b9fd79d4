#include "pcskeleton/analysis/skeleton_quality.h"

#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/skeleton/skeleton_distance.h"
#include "pcskeleton/skeleton/skeleton_structure.h"

#include <iomanip>
#include <sstream>

namespace pcskeleton {

namespace {

constexpr double kUncontractedRadiusShare = 1.0;
constexpr double kUncontractedShareWarning = 0.01;
constexpr double kOneSidedness = 0.8;
constexpr int kMinimumPointsForSideCheck = 4;

std::string count(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string percent(double share) {
    std::ostringstream s;
    s << std::setprecision(share < 0.1 ? 2 : 3) << 100.0 * share << "%";
    return s.str();
}

// Points whose contracted position is no closer to the skeleton than the surface is:
// farther from the nearest bone than the radius there. (Well contracted clouds stay
// under 0.25 radii on tubes; thick bodies leave up to 1% of their points past 0.9.)
std::size_t countUncontracted(const SkeletonGraph& skeleton, const NormalizedCloud& cloud, const PointList& contracted) {
    if (skeleton.nodeCount() == 0) return cloud.inputSize();
    const SkeletonDistance distance(skeleton);
    std::vector<char> stayed(contracted.size(), 0);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < long(contracted.size()); ++i) {
        const SkeletonProximity near = distance.nearest(cloud.toInputFrame(contracted[i]));
        stayed[i] = near.distance > kUncontractedRadiusShare * near.radius;
    }
    std::size_t uncontracted = 0;
    for (int unique : cloud.uniqueIndex) uncontracted += stayed[unique];
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

std::vector<std::string> SkeletonQuality::warnings() const {
    std::vector<std::string> w;
    if (stopReason == StopReason::IterationLimit) {
        w.push_back("Contraction stopped at the iteration limit before converging: raise the maximum iterations "
                    "or the contraction scale s_L.");
    } else if (stopReason == StopReason::NumericalFailure) {
        w.push_back("Contraction failed numerically and kept its last good positions: lower the initial "
                    "contraction weight W_L0 or the Laplacian row limit.");
    }
    if (points > 0 && uncontractedPoints > kUncontractedShareWarning * points) {
        w.push_back(count(uncontractedPoints, "point", "points") + " (" + percent(double(uncontractedPoints) / points) +
                    ") did not contract (they stayed farther from the skeleton than its radius there): "
                    "outliers, or a part too flat or thick for the iterations given. Remove outliers first, or "
                    "raise k or the maximum iterations.");
    }
    if (partsWithoutBone > 0) {
        w.push_back(count(partsWithoutBone, "part", "parts") + " of the input (" +
                    count(pointsWithoutBone, "point", "points") +
                    ") gave no bone: each collapsed to an isolated node (outlier clusters, or blob-like pieces "
                    "separate from the rest). Remove them, or lower k if they are real parts cut off.");
    }
    if (topology.isolated > 0) {
        w.push_back(count(std::size_t(topology.isolated), "node has", "nodes have") + " no bone (" +
                    count(pointsOfIsolatedNodes, "point", "points") +
                    "): outliers, or pieces too small to give a curve. Remove outliers first; delete these nodes "
                    "in Edit Skeleton.");
    }
    if (!nodesOutside.empty()) {
        w.push_back(count(nodesOutside.size(), "node lies", "nodes lie") +
                    " outside the shape (all its points on one side), e.g. where the centre of a bent part falls "
                    "outside it: lower the node spacing.");
    }
    if (!spurs.empty()) {
        w.push_back(count(spurs.size(), "short spur", "short spurs") +
                    " (limbs shorter than the body is thick where they join): usually noise. Turn on refinement, "
                    "delete them in Edit Skeleton, or raise k.");
    }
    if (!spuriousCycles.empty()) {
        w.push_back(count(spuriousCycles.size(), "loop is", "loops are") +
                    " smaller than the tube around them (no hole to go round): probably spurious. Turn on "
                    "refinement, raise the node spacing, or merge their nodes in Edit Skeleton.");
    }
    return w;
}

std::string describe(const SkeletonQuality& q) {
    std::ostringstream s;
    s << "Skeleton: " << describe(q.topology) << "; node spacing " << std::setprecision(3) << q.nodeSpacing << ".\n";
    if (q.stopReason == StopReason::NotStopped) {
        s << "Contraction: thinned from saved contracted points.\n";
    } else {
        s << "Contraction: " << count(std::size_t(q.iterations), "iteration", "iterations") << ", "
          << describe(q.stopReason) << "; mean 1-ring size " << percent(q.extentRatio) << " of the initial.\n";
    }
    s << "Input: " << count(q.points, "point", "points") << " in " << count(std::size_t(q.inputParts), "part", "parts")
      << "; " << q.uncontractedPoints << " did not contract.\n";
    s << "Tip extension: ";
    if (!q.tipsExtended) s << "off.\n";
    else if (q.tipExtension.extendedTips == 0) s << "no limb to extend.\n";
    else s << count(std::size_t(q.tipExtension.extendedTips), "limb", "limbs") << " extended, by "
           << std::setprecision(3) << q.tipExtension.meanLength << " on average, at most "
           << q.tipExtension.longest << ".\n";
    s << "Refinement: " << (q.refined ? describe(q.refinement) : std::string("off")) << ".\n";
    const std::vector<std::string> warnings = q.warnings();
    if (warnings.empty()) s << "No warnings.";
    for (std::size_t i = 0; i < warnings.size(); ++i) s << (i ? "\n" : "") << "Warning: " << warnings[i];
    return s.str();
}

}  // namespace pcskeleton
