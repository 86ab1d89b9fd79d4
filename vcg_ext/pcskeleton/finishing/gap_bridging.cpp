#include "pcskeleton/finishing/gap_bridging.h"

#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/skeleton/skeleton_structure.h"

#include <algorithm>
#include <limits>
#include <sstream>
#include <tuple>

namespace pcskeleton {

namespace {

// A tip's outward direction is measured over this many bones back along its limb: one bone
// zig-zags with the nodes' placement, and the end of a tube seen from one side, a half cap,
// contracts into a hook of a bone or two that curls towards its visible side (it would
// point at a tube beside it); the whole limb may bend. Chosen on the tuning half of the
// robustness suite (docs/benchmarks.md).
constexpr std::size_t kDirectionBones = 4;
// A node is ahead of a tip when it lies within this cosine (45 degrees) of the tip's
// outward direction: the pieces of a one-view scan lie a little inside that cone, parallel
// tubes side by side nearly square to it.
constexpr double kAheadCosine = 0.7;

// A limb ends at a node where none of the node's other bones goes on within this cosine
// (60 degrees) of its direction: at a tip, and at a corner where it turns into another
// limb (a stem whose top is hidden where a leaf leaves it). Chosen on the tuning half of
// the robustness suite, between a bend that joins two separate tubes scanned from one
// view and a corner that leaves an elephant in two (docs/benchmarks.md).
constexpr double kContinuedCosine = 0.5;

// Per bone of `node`, the outward direction of the limb that comes into `node` along it,
// when the limb ends at `node`; zero when another of the node's bones goes on that way.
std::vector<Point> endDirections(const SkeletonGraph& skeleton, const std::vector<std::vector<int>>& neighbours,
                                 int node) {
    std::vector<Point> along;
    for (const int next : neighbours[std::size_t(node)]) {
        along.push_back(chainDirection(skeleton, walkChain(neighbours, node, next), kDirectionBones));
    }
    std::vector<Point> outward;
    for (std::size_t back = 0; back < along.size(); ++back) {
        bool continued = false;
        for (std::size_t next = 0; next < along.size(); ++next) {
            continued = continued || (next != back && -along[back].dot(along[next]) > kContinuedCosine);
        }
        outward.push_back(continued ? Point(Point::Zero()) : Point(-along[back]));
    }
    return outward;
}

struct Candidate {
    double length;  // of the bone, node to node
    int from, node;
    bool operator<(const Candidate& other) const {
        return std::tie(length, from, node) < std::tie(other.length, other.from, other.node);
    }
};

// The nearest node of another piece than `from`'s whose tube is at most `maxGap` away;
// only nodes ahead of `outward` when it is given. `fromRadius` is how far `from`'s own
// data reaches towards it. The hole in the data ends at the other piece's wall, not at its
// axis: a thin leg hidden where it meets a thick body is as far from the body's axis as
// the body is thick, however short the hidden stretch. The bone goes to the nearest such
// node, as a bone between two tips of one tube goes tip to tip. node -1: none.
Candidate nearestAcrossGap(const SkeletonGraph& skeleton, const std::vector<int>& component, int from,
                           double fromRadius, double maxGap, const Point* outward) {
    Candidate nearest{std::numeric_limits<double>::infinity(), from, -1};
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
        if (component[n] == component[std::size_t(from)]) continue;
        const Point toNode = skeleton.nodes[n] - skeleton.nodes[std::size_t(from)];
        const double length = toNode.norm();
        const double gap = std::max(0.0, length - skeleton.radii[n] - fromRadius);
        const bool ahead = !outward || toNode.dot(*outward) >= kAheadCosine * length;
        if (gap <= maxGap && length < nearest.length && length > 0.0 && ahead) nearest = {length, from, int(n)};
    }
    return nearest;
}

// The bridge each limb's end and each lone node would make: the nearest node of another
// piece within the gap limit, ahead of the end.
std::vector<Candidate> bridgeCandidates(const SkeletonGraph& skeleton, const std::vector<int>& component,
                                        double maxGap) {
    std::vector<Candidate> candidates;
    // Every end of a limb, at a tip or a corner, looks ahead along the limb. A tip ends at
    // the edge of its data (tip extension comes first): its own tube reaches no farther.
    const auto neighbours = adjacencyLists(skeleton.nodeCount(), skeleton.edges);
    for (std::size_t end = 0; end < skeleton.nodeCount(); ++end) {
        for (const Point& outward : endDirections(skeleton, neighbours, int(end))) {
            if (outward.norm() == 0.0) continue;
            const Candidate nearest = nearestAcrossGap(skeleton, component, int(end), 0.0, maxGap, &outward);
            if (nearest.node >= 0) candidates.push_back(nearest);
        }
    }
    // A piece of data that thinned to a single node (a foot whose leg is hidden, a patch
    // seen between occluders) has no direction to look along: it joins the nearest node
    // of a piece whose tube comes within the same limit of its own, in any direction.
    for (std::size_t lone = 0; lone < skeleton.nodeCount(); ++lone) {
        if (!neighbours[lone].empty()) continue;
        const Candidate nearest =
            nearestAcrossGap(skeleton, component, int(lone), skeleton.radii[lone], maxGap, nullptr);
        if (nearest.node >= 0) candidates.push_back(nearest);
    }
    return candidates;
}

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
    const bool inPieces =
        std::any_of(component.begin(), component.end(), [&](int c) { return c != component.front(); });
    std::vector<Candidate> candidates;
    if (inPieces) candidates = bridgeCandidates(skeleton, component, gapLimit * nodeSpacing);

    // Nearest first, and only between pieces still apart: a bridge never closes a cycle.
    std::sort(candidates.begin(), candidates.end());
    for (const Candidate& c : candidates) {
        if (!pieces.unite(c.from, c.node)) continue;
        report.bridges.push_back({std::min(c.from, c.node), std::max(c.from, c.node)});
        report.bridgeLengths.push_back(c.length);
    }
    skeleton.edges.insert(skeleton.edges.end(), report.bridges.begin(), report.bridges.end());
    normalizeEdges(skeleton.edges);
    skeleton.inferred.insert(skeleton.inferred.end(), report.bridges.begin(), report.bridges.end());
    keepInferredWithinEdges(skeleton);
    return report;
}

}  // namespace pcskeleton
