#include "pcskeleton/finishing/skeleton_refinement.h"

#include "pcskeleton/internal/counted.h"
#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/skeleton/skeleton_structure.h"

#include <algorithm>
#include <numeric>

namespace pcskeleton {

namespace {

constexpr int kMaxPasses = 10;

// Merges each group of nodes into one; groups sharing a node merge together. The merged
// node takes the position and radius of the group's `keep` node when it has one, else the
// centroid and mean radius of its nodes. Nodes in no group stay as they are. `nodeMap`
// (node of some earlier skeleton -> node of this one) is updated to the merged skeleton.
struct NodeGroup {
    std::vector<int> nodes;
    int keep = -1;
};

void mergeGroups(SkeletonGraph& skeleton, const std::vector<NodeGroup>& groups, std::vector<int>& nodeMap) {
    const std::size_t nodeCount = skeleton.nodeCount();
    DisjointSets sets(nodeCount);
    for (const NodeGroup& group : groups) {
        for (int n : group.nodes) sets.unite(group.nodes.front(), n);
    }
    std::vector<int> kept(nodeCount, -1);
    for (const NodeGroup& group : groups) {
        if (group.keep >= 0) kept[sets.find(group.keep)] = group.keep;
    }
    std::vector<Point> positionSum(nodeCount, Point::Zero());
    std::vector<double> radiusSum(nodeCount, 0.0);
    std::vector<int> members(nodeCount, 0);
    for (std::size_t n = 0; n < nodeCount; ++n) {
        const int root = sets.find(int(n));
        positionSum[root] += skeleton.nodes[n], radiusSum[root] += skeleton.radii[n], ++members[root];
    }
    SkeletonGraph merged;
    std::vector<int> newIndex(nodeCount, -1);
    for (std::size_t n = 0; n < nodeCount; ++n) {
        const int root = sets.find(int(n));
        if (newIndex[root] < 0) {
            newIndex[root] = int(merged.nodes.size());
            const int keep = kept[root];
            merged.nodes.push_back(keep >= 0 ? skeleton.nodes[keep] : Point(positionSum[root] / members[root]));
            merged.radii.push_back(keep >= 0 ? skeleton.radii[keep] : radiusSum[root] / members[root]);
        }
        newIndex[n] = newIndex[root];
    }
    for (const Edge& e : skeleton.edges) merged.edges.push_back({newIndex[e[0]], newIndex[e[1]]});
    normalizeEdges(merged.edges);
    merged.pointNode.reserve(skeleton.pointNode.size());
    for (int node : skeleton.pointNode) merged.pointNode.push_back(node < 0 ? -1 : newIndex[node]);
    skeleton = std::move(merged);
    for (int& node : nodeMap) node = newIndex[node];
}

// Spurs and redundant limbs, and corner limbs, all judged on the same skeleton: each limb
// with the junction it goes into.
struct LimbsToRemove {
    std::vector<NodeGroup> groups;
    int spurs = 0, corners = 0;
};

LimbsToRemove limbsToRemove(const SkeletonGraph& skeleton, const PointList& points, double nodeSpacing) {
    LimbsToRemove limbs;
    const std::vector<std::vector<int>> nodePoints = pointsOfNodes(skeleton);
    for (const Limb& limb : tipLimbs(skeleton)) {
        if (isSpur(skeleton, limb, nodeSpacing) || isRedundantLimb(skeleton, limb, points, nodePoints, nodeSpacing)) {
            ++limbs.spurs;
        } else if (isCornerLimb(skeleton, limb, points, nodePoints)) {
            ++limbs.corners;
        } else {
            continue;
        }
        limbs.groups.push_back({limb.path, limb.path.back()});
    }
    return limbs;
}

std::vector<NodeGroup> stragglingEndGroups(const SkeletonGraph& skeleton, double nodeSpacing) {
    std::vector<NodeGroup> groups;
    for (std::vector<int>& end : stragglingEnds(skeleton, pointsOfNodes(skeleton), nodeSpacing)) {
        const int keeper = end.back();
        groups.push_back({std::move(end), keeper});
    }
    return groups;
}

std::vector<NodeGroup> spuriousCycleGroups(const SkeletonGraph& skeleton, double nodeSpacing) {
    std::vector<NodeGroup> groups;
    for (std::vector<int>& cycle : shortCycleBasis(skeleton)) {
        if (isSpuriousCycle(skeleton, cycle, nodeSpacing)) groups.push_back({std::move(cycle), -1});
    }
    return groups;
}

// Removes a bone of the graph; its edges must be sorted (normalizeEdges).
void eraseBone(SkeletonGraph& skeleton, Edge bone) {
    if (bone[0] > bone[1]) std::swap(bone[0], bone[1]);
    skeleton.edges.erase(std::lower_bound(skeleton.edges.begin(), skeleton.edges.end(), bone));
}

// Each loop whose bone must go is opened there, if it is still whole: a cut never splits
// the skeleton. Returns how many were opened.
int openLoops(SkeletonGraph& skeleton, const std::vector<LoopToOpen>& loops) {
    int cuts = 0;
    for (const LoopToOpen& loop : loops) {
        bool whole = true;
        for (std::size_t i = 0; i < loop.cycle.size() && whole; ++i) {
            Edge e{loop.cycle[i], loop.cycle[(i + 1) % loop.cycle.size()]};
            if (e[0] > e[1]) std::swap(e[0], e[1]);
            whole = std::binary_search(skeleton.edges.begin(), skeleton.edges.end(), e);
        }
        if (!whole) continue;
        eraseBone(skeleton, loop.bone);
        ++cuts;
    }
    return cuts;
}

// Contact loops, then loops the data fills (skeleton_structure.h), each opened at its bone.
// Contacts are measured once, on the loops thinning gave: after a cut the basis may pair
// what is left of a loop with a neighbouring one and measure the two as one narrow loop (the
// paper's misaligned_scans_0.015 lost a real hole of Fertility that way).
// Returns how many were opened, each counted in `report`.
int openLoopsWithoutHoles(SkeletonGraph& skeleton, const PointList& points, double nodeSpacing,
                          const RefinementLimits& limits, RefinementReport& report) {
    normalizeEdges(skeleton.edges);  // sorted, for the searches in openLoops
    const int contactCuts = openLoops(skeleton, contactLoops(skeleton, points, limits));
    // Then the loops over data, on the skeleton as the contacts left it. Where two of them share
    // a bone, opening one leaves their union, which goes round the same points: they are
    // measured again until none is left. (A union with a real hole keeps that hole's empty
    // disc, and stays.)
    int filledCuts = 0;
    for (std::vector<LoopToOpen> filled = filledLoops(skeleton, points, nodeSpacing, limits); !filled.empty();
         filled = filledLoops(skeleton, points, nodeSpacing, limits)) {
        filledCuts += openLoops(skeleton, filled);  // the first loop of a basis is whole: at least one
    }
    report.cyclesCut += contactCuts;
    report.filledLoopsCut += filledCuts;
    return contactCuts + filledCuts;
}

// Cuts the first of the bones `find` gives, then asks again, until it gives none: a cut
// may leave the next one the only way between its parts. Returns how many were cut.
template <typename FindBones>
int cutOneAtATime(SkeletonGraph& skeleton, const FindBones& find) {
    normalizeEdges(skeleton.edges);  // sorted, for eraseBone; erasing keeps them so
    int cuts = 0;
    for (std::vector<Edge> bones = find(); !bones.empty(); bones = find()) {
        eraseBone(skeleton, bones.front());
        ++cuts;
    }
    return cuts;
}

// Bones across gaps (skeleton_structure.h), most stretched first.
int cutBonesAcrossGaps(SkeletonGraph& skeleton, double nodeSpacing, double minStretch) {
    return cutOneAtATime(skeleton, [&] { return bonesAcrossGaps(skeleton, nodeSpacing, minStretch); });
}

// Bones over gaps in the data (skeleton_structure.h), widest gap first.
int cutBonesOverDataGaps(SkeletonGraph& skeleton, const PointList& points, double minStretch) {
    const std::vector<std::vector<int>> nodePoints = pointsOfNodes(skeleton);  // cuts keep every node's points
    return cutOneAtATime(skeleton, [&] { return bonesOverDataGaps(skeleton, points, nodePoints, minStretch); });
}

// A stray bridge (skeleton_structure.h) is cut at its far end, and its nodes (a handful
// of points) are absorbed into the junction it then hangs from, which keeps its place.
// One at a time: a cut may leave the next bridge the only way between its parts.
std::vector<NodeGroup> strayBridgeGroups(SkeletonGraph& skeleton) {
    normalizeEdges(skeleton.edges);  // sorted, for the search below
    std::vector<std::vector<int>> bridges = strayBridges(skeleton, pointsOfNodes(skeleton));
    if (bridges.empty()) return {};
    std::vector<int>& bridge = bridges.front();
    const int beforeEnd = bridge[bridge.size() - 2], end = bridge.back();
    eraseBone(skeleton, Edge{beforeEnd, end});
    bridge.pop_back();
    const int junction = bridge.front();
    return {{std::move(bridge), junction}};
}

std::vector<NodeGroup> closeJunctionGroups(const SkeletonGraph& skeleton, double nodeSpacing) {
    std::vector<NodeGroup> groups;
    for (std::vector<int>& path : closeJunctionPaths(skeleton, nodeSpacing)) groups.push_back({std::move(path), -1});
    return groups;
}

}  // namespace

std::string describe(const RefinementReport& r) {
    return "removed " + counted(std::size_t(r.spursRemoved), "spur") + " and " +
           counted(std::size_t(r.cornerLimbsRemoved), "corner limb") + ", trimmed " +
           counted(std::size_t(r.endsTrimmed), "straggling end") + ", collapsed " +
           counted(std::size_t(r.cyclesCollapsed), "small loop") + ", cut " +
           counted(std::size_t(r.cyclesCut), "narrow loop") + ", " + counted(std::size_t(r.bridgesCut), "stray bridge") +
           ", " + counted(std::size_t(r.filledLoopsCut), "loop") + " over data, merged " +
           counted(std::size_t(r.junctionsMerged), "pair") + " of close junctions";
}

RefinementReport refineSkeleton(SkeletonGraph& skeleton, const PointList& points, double nodeSpacing,
                                const RefinementLimits& refinementLimits) {
    RefinementReport report;
    report.nodeMap.resize(skeleton.nodeCount());
    std::iota(report.nodeMap.begin(), report.nodeMap.end(), 0);
    // Each step merges before the next looks: it must see the graph the others left.
    auto merge = [&](const std::vector<NodeGroup>& groups) {
        mergeGroups(skeleton, groups, report.nodeMap);
        return int(groups.size());
    };
    for (int pass = 0; pass < kMaxPasses; ++pass) {
        const LimbsToRemove limbs = limbsToRemove(skeleton, points, nodeSpacing);
        merge(limbs.groups);
        const int spurs = limbs.spurs, corners = limbs.corners;
        const int ends = merge(stragglingEndGroups(skeleton, nodeSpacing));
        const int cycles = merge(spuriousCycleGroups(skeleton, nodeSpacing));
        const int cuts = pass == 0 ? openLoopsWithoutHoles(skeleton, points, nodeSpacing, refinementLimits, report) : 0;
        // Two statements: the bones go first, and the operands of + have no set order.
        const int gapBones = cutBonesAcrossGaps(skeleton, nodeSpacing, refinementLimits.gapStretch);
        const int bridges = gapBones + merge(strayBridgeGroups(skeleton));
        const int junctions = merge(closeJunctionGroups(skeleton, nodeSpacing));
        report.spursRemoved += spurs;
        report.cornerLimbsRemoved += corners;
        report.endsTrimmed += ends;
        report.cyclesCollapsed += cycles;
        report.bridgesCut += bridges;
        report.junctionsMerged += junctions;
        if (spurs + corners + ends + cycles + cuts + bridges + junctions > 0) continue;
        // Last, once the steps above leave the skeleton as it is: where a stray bridge joins
        // a limb's end to another part, they absorb the bridge's nodes, and a cut there
        // would leave them as a limb of their own.
        const int dataGapBones = cutBonesOverDataGaps(skeleton, points, refinementLimits.gapStretch);
        report.bridgesCut += dataGapBones;
        if (dataGapBones == 0) break;
    }
    return report;
}

}  // namespace pcskeleton
