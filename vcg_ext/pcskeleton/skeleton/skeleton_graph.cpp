#include "pcskeleton/skeleton/skeleton_graph.h"

#include "pcskeleton/internal/counted.h"
#include "pcskeleton/internal/disjoint_sets.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <iterator>
#include <sstream>

namespace pcskeleton {

std::vector<int> nodeDegrees(std::size_t nodeCount, const std::vector<Edge>& edges) {
    std::vector<int> degree(nodeCount, 0);
    for (const Edge& e : edges) ++degree[e[0]], ++degree[e[1]];
    return degree;
}

std::vector<std::vector<int>> adjacencyLists(std::size_t nodeCount, const std::vector<Edge>& edges) {
    std::vector<std::vector<int>> neighbours(nodeCount);
    for (const Edge& e : edges) {
        neighbours[e[0]].push_back(e[1]);
        neighbours[e[1]].push_back(e[0]);
    }
    return neighbours;
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
    return counted(std::size_t(t.nodes), "node") + ", " + counted(std::size_t(t.edges), "edge") + ", " +
           counted(std::size_t(t.components), "component") + ", " + counted(std::size_t(t.cycles), "cycle") + ", " +
           counted(std::size_t(t.tips), "tip") + ", " + counted(std::size_t(t.junctions), "junction");
}

std::vector<double> meanDistanceToNodes(const PointList& points, const std::vector<int>& pointNode,
                                        const PointList& nodes) {
    std::vector<double> distance(nodes.size(), 0.0);
    std::vector<std::size_t> members(nodes.size(), 0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const int node = pointNode[i];
        if (node < 0) continue;
        distance[node] += (points[i] - nodes[node]).norm();
        ++members[node];
    }
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (members[n] > 0) distance[n] /= double(members[n]);
    }
    return distance;
}

std::vector<std::vector<int>> pointsOfNodes(const SkeletonGraph& graph) {
    std::vector<std::vector<int>> points(graph.nodeCount());
    for (std::size_t i = 0; i < graph.pointNode.size(); ++i) {
        if (graph.pointNode[i] >= 0) points[graph.pointNode[i]].push_back(int(i));
    }
    return points;
}

void normalizeEdges(std::vector<Edge>& edges) {
    for (Edge& e : edges) {
        if (e[0] > e[1]) std::swap(e[0], e[1]);
    }
    edges.erase(std::remove_if(edges.begin(), edges.end(), [](const Edge& e) { return e[0] == e[1]; }), edges.end());
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
}

bool hasEdge(const std::vector<Edge>& edges, int a, int b) {
    const Edge wanted = edgeBetween(a, b);
    return std::find(edges.begin(), edges.end(), wanted) != edges.end();
}

void keepInferredWithinEdges(SkeletonGraph& graph) {
    normalizeEdges(graph.inferred);
    std::vector<Edge> sortedEdges = graph.edges;
    std::sort(sortedEdges.begin(), sortedEdges.end());
    std::vector<Edge> kept;
    std::set_intersection(graph.inferred.begin(), graph.inferred.end(), sortedEdges.begin(), sortedEdges.end(),
                          std::back_inserter(kept));
    graph.inferred = std::move(kept);
}

std::vector<char> inferredFlags(const SkeletonGraph& graph) {
    std::vector<char> flags;
    flags.reserve(graph.edges.size());
    for (const Edge& e : graph.edges) {
        const Edge sorted = edgeBetween(e[0], e[1]);
        flags.push_back(std::binary_search(graph.inferred.begin(), graph.inferred.end(), sorted) ? 1 : 0);
    }
    return flags;
}

std::string invariantViolation(const SkeletonGraph& graph) {
    const int nodeCount = static_cast<int>(graph.nodeCount());
    std::ostringstream why;
    if (graph.radii.size() != graph.nodes.size()) {
        why << graph.nodes.size() << " nodes but " << graph.radii.size() << " radii";
        return why.str();
    }
    for (int n = 0; n < nodeCount; ++n) {
        if (!graph.nodes[n].allFinite()) {
            why << "node " << n << " has a non-finite position";
            return why.str();
        }
        if (!isPositiveFinite(graph.radii[n])) {
            why << "node " << n << " has radius " << graph.radii[n] << " (radii must be positive)";
            return why.str();
        }
    }
    std::vector<Edge> sorted;
    sorted.reserve(graph.edges.size());
    for (const Edge& e : graph.edges) {
        if (e[0] < 0 || e[1] < 0 || e[0] >= nodeCount || e[1] >= nodeCount) {
            why << "edge " << e[0] << "-" << e[1] << " names a node that does not exist";
            return why.str();
        }
        if (e[0] == e[1]) {
            why << "node " << e[0] << " is connected to itself";
            return why.str();
        }
        sorted.push_back(edgeBetween(e[0], e[1]));
    }
    std::sort(sorted.begin(), sorted.end());
    const auto twin = std::adjacent_find(sorted.begin(), sorted.end());
    if (twin != sorted.end()) {
        why << "nodes " << (*twin)[0] << " and " << (*twin)[1] << " are connected twice";
        return why.str();
    }
    for (const Edge& e : graph.inferred) {
        if (!std::binary_search(sorted.begin(), sorted.end(), edgeBetween(e[0], e[1]))) {
            why << "the inferred bone " << e[0] << "-" << e[1] << " is not a bone";
            return why.str();
        }
    }
    for (int node : graph.pointNode) {
        if (node < -1 || node >= nodeCount) {
            why << "a point belongs to node " << node << ", which does not exist";
            return why.str();
        }
    }
    return {};
}

int fillMissingRadii(SkeletonGraph& graph) {
    const std::size_t nodeCount = graph.nodeCount();
    graph.radii.resize(nodeCount, 0.0);
    const std::vector<std::vector<int>> neighbours = adjacencyLists(nodeCount, graph.edges);
    std::vector<bool> known(nodeCount);
    std::vector<int> frontier;
    int missing = 0;
    for (std::size_t n = 0; n < nodeCount; ++n) {
        known[n] = isPositiveFinite(graph.radii[n]);
        if (known[n]) frontier.push_back(static_cast<int>(n));
        else ++missing;
    }
    if (missing == 0) return 0;

    // Breadth-first from the nodes that have a radius, one ring of unknown nodes at a time,
    // so each takes the radii of the nearest known nodes only.
    std::vector<bool> inRing(nodeCount, false);
    while (!frontier.empty()) {
        std::vector<int> ring;
        for (int n : frontier) {
            for (int m : neighbours[n]) {
                if (!known[m] && !inRing[m]) ring.push_back(m), inRing[m] = true;
            }
        }
        std::vector<double> filled(ring.size(), 0.0);
        for (std::size_t i = 0; i < ring.size(); ++i) {
            int sources = 0;
            for (int m : neighbours[ring[i]]) {
                if (known[m]) filled[i] += graph.radii[m], ++sources;
            }
            filled[i] /= sources;
        }
        for (std::size_t i = 0; i < ring.size(); ++i) graph.radii[ring[i]] = filled[i], known[ring[i]] = true;
        frontier = std::move(ring);
    }

    // Components without any radius.
    const Eigen::AlignedBox3d extent = boundingBox(graph.nodes);
    const double extentFallback = nodeCount > 0 && extent.diagonal().norm() > 0.0 ? 0.01 * extent.diagonal().norm() : 1.0;
    DisjointSets sets(nodeCount);
    for (const Edge& e : graph.edges) sets.unite(e[0], e[1]);
    std::vector<double> boneLength(nodeCount, 0.0);
    std::vector<int> bones(nodeCount, 0);
    for (const Edge& e : graph.edges) {
        const int root = sets.find(e[0]);
        boneLength[root] += (graph.nodes[e[0]] - graph.nodes[e[1]]).norm();
        ++bones[root];
    }
    for (std::size_t n = 0; n < nodeCount; ++n) {
        if (known[n]) continue;
        const int root = sets.find(static_cast<int>(n));
        const double halfBone = bones[root] > 0 ? 0.5 * boneLength[root] / bones[root] : 0.0;
        graph.radii[n] = halfBone > 0.0 ? halfBone : extentFallback;
    }
    return missing;
}

}  // namespace pcskeleton
