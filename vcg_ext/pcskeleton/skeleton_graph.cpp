#include "pcskeleton/skeleton_graph.h"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace pcskeleton {

namespace {

class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    int find(int i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    bool unite(int a, int b) {
        a = find(a), b = find(b);
        if (a == b) return false;
        parent_[b] = a;
        return true;
    }

private:
    std::vector<int> parent_;
};

const char* plural(int n, const char* one, const char* many) { return n == 1 ? one : many; }

}  // namespace

std::vector<int> nodeDegrees(std::size_t nodeCount, const std::vector<Edge>& edges) {
    std::vector<int> degree(nodeCount, 0);
    for (const Edge& e : edges) ++degree[e[0]], ++degree[e[1]];
    return degree;
}

SkeletonTopology analyseTopology(std::size_t nodeCount, const std::vector<Edge>& edges) {
    SkeletonTopology t;
    t.nodes = static_cast<int>(nodeCount);
    t.edges = static_cast<int>(edges.size());
    DisjointSets sets(nodeCount);
    int merges = 0;
    for (const Edge& e : edges) merges += sets.unite(e[0], e[1]) ? 1 : 0;
    t.components = t.nodes - merges;
    t.cycles = t.edges - t.nodes + t.components;
    for (int degree : nodeDegrees(nodeCount, edges)) {
        if (degree == 0) ++t.isolated;
        if (degree == 1) ++t.tips;
        if (degree >= 3) ++t.junctions;
    }
    return t;
}

std::string describe(const SkeletonTopology& t) {
    std::ostringstream s;
    s << t.nodes << plural(t.nodes, " node, ", " nodes, ") << t.edges << plural(t.edges, " edge, ", " edges, ")
      << t.components << plural(t.components, " component, ", " components, ") << t.cycles
      << plural(t.cycles, " cycle, ", " cycles, ") << t.tips << plural(t.tips, " tip, ", " tips, ") << t.junctions
      << plural(t.junctions, " junction", " junctions");
    return s.str();
}

void normalizeEdges(std::vector<Edge>& edges) {
    for (Edge& e : edges) {
        if (e[0] > e[1]) std::swap(e[0], e[1]);
    }
    edges.erase(std::remove_if(edges.begin(), edges.end(), [](const Edge& e) { return e[0] == e[1]; }), edges.end());
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
}

}  // namespace pcskeleton
