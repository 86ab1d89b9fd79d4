// Small skeleton graphs built by hand, whose flaws (spurs, false loops) are known, for the
// tests of the structure, refinement and tip-extension units.
#pragma once

#include <pcskeleton/skeleton/skeleton_graph.h>

namespace pcskeleton::graphs {

constexpr double kSpacing = 0.1;

// Nodes 0..10 along the x axis, kSpacing apart, radius 0.2.
inline SkeletonGraph straightChain() {
    SkeletonGraph g;
    for (int i = 0; i <= 10; ++i) {
        g.nodes.emplace_back(kSpacing * i, 0, 0);
        g.radii.push_back(0.2);
        if (i > 0) g.edges.push_back({i - 1, i});
    }
    return g;
}

// Adds a node of radius 0.2 at `p`, joined to `connectTo`; returns its index.
inline int addNode(SkeletonGraph& g, const Point& p, int connectTo) {
    g.nodes.push_back(p);
    g.radii.push_back(0.2);
    const int n = int(g.nodeCount()) - 1;
    g.edges.push_back({connectTo, n});
    normalizeEdges(g.edges);
    return n;
}

// Gives each point to the node nearest to it (the first of equally near ones), as thinning
// would: replaces g.pointNode.
inline void giveEachPointItsNearestNode(SkeletonGraph& g, const PointList& points) {
    g.pointNode.assign(points.size(), 0);
    for (std::size_t p = 0; p < points.size(); ++p) {
        for (std::size_t n = 1; n < g.nodeCount(); ++n) {
            if ((points[p] - g.nodes[n]).squaredNorm() < (points[p] - g.nodes[std::size_t(g.pointNode[p])]).squaredNorm()) {
                g.pointNode[p] = int(n);
            }
        }
    }
}

}  // namespace pcskeleton::graphs
