#include "pcskeleton/skeleton/skeleton_thinning.h"

#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/internal/spatial_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <set>

namespace pcskeleton {

namespace {

// A link is stretched only if contraction also made it this many times longer than it
// was: along a bone links shrink or keep their length, so sparse clouds, whose links are
// several node spacings long from the start, keep theirs (docs/benchmarks.md#measurements-behind-the-constants).
constexpr double kStretchFactor = 2.0;

int farthestFromCentroid(const PointList& points) {
    Point centroid = Point::Zero();
    for (const Point& p : points) centroid += p;
    centroid /= static_cast<double>(points.size());
    int best = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        if ((points[i] - centroid).squaredNorm() > (points[best] - centroid).squaredNorm()) best = int(i);
    }
    return best;
}

}  // namespace

SampledPoints farthestPointSampling(const PointList& points, double radius) {
    SampledPoints result;
    if (points.empty()) return result;
    const PointIndex index(points);
    std::vector<double> distance(points.size(), std::numeric_limits<double>::infinity());
    result.owner.assign(points.size(), -1);

    // Max-heap of (distance to nearest sample, point); outdated entries are skipped.
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry> farthest;
    std::vector<int> nearby;
    int next = farthestFromCentroid(points);
    double nextDistance = std::numeric_limits<double>::infinity();
    while (true) {
        const int sample = static_cast<int>(result.samples.size());
        result.samples.push_back(next);
        // Only points closer to the new sample than to their current one change owner,
        // and none of them is farther from it than the farthest point overall.
        if (std::isinf(nextDistance)) {
            nearby.resize(points.size());
            std::iota(nearby.begin(), nearby.end(), 0);
        } else {
            index.withinRadius(points[next], nextDistance, nearby);
        }
        for (int i : nearby) {
            const double d = (points[i] - points[next]).norm();
            if (d < distance[i]) {
                distance[i] = d;
                result.owner[i] = sample;
                farthest.emplace(d, i);
            }
        }
        while (!farthest.empty() && farthest.top().first != distance[farthest.top().second]) farthest.pop();
        if (farthest.empty() || farthest.top().first <= radius) break;
        next = farthest.top().second;
        nextDistance = farthest.top().first;
    }
    return result;
}

std::vector<Edge> connectByOneRings(const OneRings& rings, const std::vector<int>& owner, const PointList& original,
                                    const PointList& contracted, double maxLinkLength) {
    std::vector<Edge> edges;
    std::vector<std::pair<double, Edge>> stretched;  // (squared contracted length, owners)
    const double maxSquared = maxLinkLength * maxLinkLength;
    for (std::size_t i = 0; i < rings.size(); ++i) {
        for (const int* j = rings.ringBegin(i); j != rings.ringEnd(i); ++j) {
            if (owner[i] == owner[*j]) continue;
            const double squared = (contracted[i] - contracted[*j]).squaredNorm();
            const double grown = kStretchFactor * kStretchFactor * (original[i] - original[*j]).squaredNorm();
            if (squared <= maxSquared || squared <= grown) {
                edges.push_back({owner[i], owner[*j]});
            } else {
                stretched.push_back({squared, {owner[i], owner[*j]}});
            }
        }
    }
    // A stretched link joins points that contraction pulled to different bones (parts that
    // touch, noise across a gap): it would close a cycle the shape does not have. It still
    // connects samples that nothing else connects, shortest first, so that parts which
    // contracted less do not fall apart; it never closes a cycle.
    if (!stretched.empty()) {
        std::sort(stretched.begin(), stretched.end());
        DisjointSets parts(owner.empty() ? 0 : std::size_t(*std::max_element(owner.begin(), owner.end())) + 1);
        for (const Edge& e : edges) parts.unite(e[0], e[1]);
        for (const auto& link : stretched) {
            if (parts.unite(link.second[0], link.second[1])) edges.push_back(link.second);
        }
    }
    normalizeEdges(edges);
    return edges;
}

namespace {

// The graph while triangles are collapsed: node ids stay stable, merged nodes die.
class CollapsibleGraph {
public:
    explicit CollapsibleGraph(const ThinnedGraph& graph)
        : position_(graph.nodes), neighbours_(graph.nodes.size()), mergedInto_(graph.nodes.size(), -1) {
        for (const Edge& e : graph.edges) {
            neighbours_[e[0]].insert(e[1]);
            neighbours_[e[1]].insert(e[0]);
        }
        for (const Edge& e : graph.edges) push(e[0], e[1]);
    }

    void collapseAllTriangles() {
        while (!queue_.empty()) {
            const Candidate c = queue_.top();
            queue_.pop();
            if (!isCurrent(c) || !onTriangle(c.a, c.b)) continue;
            collapse(c.a, c.b);
        }
    }

    void writeTo(ThinnedGraph& graph) const {
        std::vector<int> newId(position_.size(), -1);
        graph.nodes.clear();
        for (std::size_t i = 0; i < position_.size(); ++i) {
            if (mergedInto_[i] >= 0) continue;
            newId[i] = static_cast<int>(graph.nodes.size());
            graph.nodes.push_back(position_[i]);
        }
        graph.edges.clear();
        for (std::size_t i = 0; i < position_.size(); ++i) {
            if (newId[i] < 0) continue;
            for (int j : neighbours_[i]) {
                if (int(i) < j) graph.edges.push_back({newId[i], newId[j]});
            }
        }
        normalizeEdges(graph.edges);
        for (int& node : graph.owner) node = newId[survivor(node)];
    }

private:
    struct Candidate {
        double length;
        int a, b;
        bool operator<(const Candidate& other) const { return length > other.length; }  // shortest on top
    };

    double length(int a, int b) const { return (position_[a] - position_[b]).norm(); }
    void push(int a, int b) { queue_.push({length(a, b), a, b}); }

    bool isCurrent(const Candidate& c) const {
        return mergedInto_[c.a] < 0 && mergedInto_[c.b] < 0 && neighbours_[c.a].count(c.b) &&
               c.length == length(c.a, c.b);
    }

    bool onTriangle(int a, int b) const {
        const auto& small = neighbours_[a].size() < neighbours_[b].size() ? neighbours_[a] : neighbours_[b];
        const auto& large = &small == &neighbours_[a] ? neighbours_[b] : neighbours_[a];
        return std::any_of(small.begin(), small.end(), [&](int c) { return large.count(c) > 0; });
    }

    // b merges into a, at the edge's midpoint.
    void collapse(int a, int b) {
        position_[a] = 0.5 * (position_[a] + position_[b]);
        mergedInto_[b] = a;
        for (int c : neighbours_[b]) {
            neighbours_[c].erase(b);
            if (c != a) {
                neighbours_[c].insert(a);
                neighbours_[a].insert(c);
            }
        }
        neighbours_[b].clear();
        neighbours_[a].erase(b);
        // a's edges changed length, and a triangle can only appear through a: re-queue both.
        for (int c : neighbours_[a]) {
            push(a, c);
            for (int d : neighbours_[c]) {
                if (c < d && neighbours_[a].count(d)) push(c, d);
            }
        }
    }

    int survivor(int node) const {
        while (mergedInto_[node] >= 0) node = mergedInto_[node];
        return node;
    }

    PointList position_;
    std::vector<std::set<int>> neighbours_;
    std::vector<int> mergedInto_;
    std::priority_queue<Candidate> queue_;
};

}  // namespace

void collapseTriangles(ThinnedGraph& graph) {
    CollapsibleGraph collapsible(graph);
    collapsible.collapseAllTriangles();
    collapsible.writeTo(graph);
}

ThinnedGraph thinContractedPoints(const PointList& original, const PointList& contracted, const OneRings& rings,
                                  double radius, double maxLinkLength, const ProgressCallback& progress) {
    report(progress, 0, "Sampling contracted points");
    SampledPoints sampled = farthestPointSampling(contracted, radius);
    ThinnedGraph graph;
    for (int s : sampled.samples) graph.nodes.push_back(contracted[s]);
    report(progress, 50, "Connecting samples");
    graph.edges = connectByOneRings(rings, sampled.owner, original, contracted, maxLinkLength);
    graph.owner = std::move(sampled.owner);
    report(progress, 70, "Collapsing triangles");
    collapseTriangles(graph);
    report(progress, 100, "Thinning done");
    return graph;
}

}  // namespace pcskeleton
