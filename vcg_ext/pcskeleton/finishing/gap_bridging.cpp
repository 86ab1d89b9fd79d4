#include "pcskeleton/finishing/gap_bridging.h"

#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/skeleton/skeleton_structure.h"

#include <algorithm>
#include <sstream>
#include <tuple>

namespace pcskeleton {

namespace {

// A tip's outward direction is measured over this many bones back along its limb: one bone
// zig-zags with the nodes' placement, the whole limb may bend.
constexpr std::size_t kDirectionBones = 3;
// A node is ahead of a tip when it lies within this cosine (45 degrees) of the tip's
// outward direction. On the robustness suite the pieces of one-view scans lie 37-41
// degrees off their tips' direction; the close parallel tubes lie 80-90 degrees off.
constexpr double kAheadCosine = 0.7;

struct Candidate {
    double length;
    int tip, node;
    bool operator<(const Candidate& other) const {
        return std::tie(length, tip, node) < std::tie(other.length, other.tip, other.node);
    }
};

}  // namespace

std::string describe(const GapBridgingReport& report) {
    if (report.bridges.empty()) return "none bridged";
    std::ostringstream text;
    text << report.bridges.size() << " bridged, ";
    text.precision(3);
    for (std::size_t b = 0; b < report.bridgeLengths.size(); ++b) text << (b ? ", " : "") << report.bridgeLengths[b];
    text << " long";
    return text.str();
}

GapBridgingReport bridgeGaps(SkeletonGraph& skeleton, double nodeSpacing, double gapLimit) {
    GapBridgingReport report;
    if (!(gapLimit > 0.0) || skeleton.nodeCount() < 2) return report;
    DisjointSets pieces(skeleton.nodeCount());
    for (const Edge& e : skeleton.edges) pieces.unite(e[0], e[1]);
    std::vector<int> component(skeleton.nodeCount());  // each node's piece before any bridge
    for (std::size_t n = 0; n < component.size(); ++n) component[n] = pieces.find(int(n));
    const double maxLength = gapLimit * nodeSpacing;

    std::vector<Candidate> candidates;
    for (const Limb& limb : tipLimbs(skeleton)) {
        const int tip = limb.path.front();
        const int back = limb.path[std::min(kDirectionBones, limb.path.size() - 1)];
        Point outward = skeleton.nodes[tip] - skeleton.nodes[back];
        if (outward.norm() == 0.0) continue;
        outward.normalize();
        Candidate nearest{maxLength, -1, -1};
        for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
            if (component[n] == component[tip]) continue;
            const Point toNode = skeleton.nodes[n] - skeleton.nodes[tip];
            const double length = toNode.norm();
            if (length <= nearest.length && length > 0.0 && toNode.dot(outward) >= kAheadCosine * length) {
                nearest = {length, tip, int(n)};
            }
        }
        if (nearest.node >= 0) candidates.push_back(nearest);
    }

    // Shortest first, and only between pieces still apart: a bridge never closes a cycle.
    std::sort(candidates.begin(), candidates.end());
    for (const Candidate& c : candidates) {
        if (!pieces.unite(c.tip, c.node)) continue;
        report.bridges.push_back({std::min(c.tip, c.node), std::max(c.tip, c.node)});
        report.bridgeLengths.push_back(c.length);
    }
    skeleton.edges.insert(skeleton.edges.end(), report.bridges.begin(), report.bridges.end());
    normalizeEdges(skeleton.edges);
    skeleton.inferred.insert(skeleton.inferred.end(), report.bridges.begin(), report.bridges.end());
    keepInferredWithinEdges(skeleton);
    return report;
}

}  // namespace pcskeleton
