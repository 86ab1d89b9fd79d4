// The curve skeleton: nodes, bones, per-node radius and the input points each node
// stands for (the correspondence), plus the topology numbers users check first.
#pragma once

#include "pcskeleton/contraction/point_cloud_input.h"

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <vector>

namespace pcskeleton {

using Edge = std::array<int, 2>;  // node indices, smaller first

// The edge between nodes a and b as edge lists hold it (its lower-numbered end first).
inline Edge edgeBetween(int a, int b) { return Edge{std::min(a, b), std::max(a, b)}; }

struct SkeletonGraph {
    PointList nodes;              // input frame
    std::vector<Edge> edges;      // sorted, no duplicates, no self-loops
    // Per node: the radius of the tube around it. Along a bone, measured across the bone
    // with noise taken out (finishing/bone_radii.h); at tips, junctions and where the
    // points are no tube's wall, the mean distance to its corresponding input points.
    std::vector<double> radii;
    std::vector<int> pointNode;   // per input point: the node it belongs to (-1 = none)
    // Bones the data does not show but the skeleton infers (a gap in a scan bridged): a
    // sorted subset of `edges`, so that a user sees what was guessed.
    std::vector<Edge> inferred;

    std::size_t nodeCount() const { return nodes.size(); }
    std::size_t edgeCount() const { return edges.size(); }
};

struct SkeletonTopology {
    int nodes = 0, edges = 0;
    int components = 0;  // connected components
    int cycles = 0;      // independent cycles (first Betti number): edges - nodes + components
    int tips = 0;        // nodes of degree 1
    int junctions = 0;   // nodes of degree 3 or more
    int isolated = 0;    // nodes of degree 0
};

SkeletonTopology analyseTopology(std::size_t nodeCount, const std::vector<Edge>& edges);
inline SkeletonTopology analyseTopology(const SkeletonGraph& graph) {
    return analyseTopology(graph.nodeCount(), graph.edges);
}

// "12 nodes, 11 edges, 1 component, 0 cycles, 2 tips, 0 junctions"
std::string describe(const SkeletonTopology& topology);

// Node degrees, one per node.
std::vector<int> nodeDegrees(std::size_t nodeCount, const std::vector<Edge>& edges);

// Each node's neighbours along the bones.
std::vector<std::vector<int>> adjacencyLists(std::size_t nodeCount, const std::vector<Edge>& edges);

// Each node's points: the indices i with graph.pointNode[i] == node, ascending.
std::vector<std::vector<int>> pointsOfNodes(const SkeletonGraph& graph);

// For each node, the mean distance from its points to `nodes[n]` (0 for a node without
// points): the radius the embedding gives it. pointNode[i] is point i's node, -1 for none.
std::vector<double> meanDistanceToNodes(const PointList& points, const std::vector<int>& pointNode,
                                        const PointList& nodes);

// Sorts the edges, orders each edge's ends, drops duplicates and self-loops.
void normalizeEdges(std::vector<Edge>& edges);

// Whether a and b are joined by an edge, whichever end is named first.
bool hasEdge(const std::vector<Edge>& edges, int a, int b);

// Normalises graph.inferred as the edges and keeps only the inferred bones that are still
// edges (after an edit removed or renumbered some).
void keepInferredWithinEdges(SkeletonGraph& graph);

// Per edge, in graph.edges' order: 1 for an inferred bone, 0 for one the data shows.
std::vector<char> inferredFlags(const SkeletonGraph& graph);

// A usable radius (or radius factor): positive and finite.
inline bool isPositiveFinite(double value) { return value > 0.0 && value < std::numeric_limits<double>::infinity(); }

// Empty when the graph is valid, else the first broken rule, meant for the user: one
// radius per node, finite positions, edges between existing nodes, no self-loop, no
// duplicate edge, radii positive and finite, correspondence naming existing nodes or -1,
// inferred bones among the edges.
std::string invariantViolation(const SkeletonGraph& graph);

// Gives every node whose radius is missing (zero, negative, not finite) a usable one: the
// mean radius of its nearest nodes along the bones that have one; in a component with no
// radius at all, half its mean bone length (or 1% of the nodes' extent when it has no
// bone). A node owning a single point, or a skeleton read from a format without radii,
// needs this before editing or reconstruction. Returns how many radii were filled.
int fillMissingRadii(SkeletonGraph& graph);

}  // namespace pcskeleton
