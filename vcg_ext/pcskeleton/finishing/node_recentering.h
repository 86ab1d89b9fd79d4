// Nodes of one-sided data moved to the centre of their cross-section. Where a node's
// points cover only part of the cross-section around its bone (a scan from one side, a
// hole), the centre of its points, where the paper's embedding puts it, lies on the
// visible wall. Such a node moves to the centre of the circle that fits its points in the
// plane across the bone (an algebraic least-squares fit), and takes that circle's radius;
// when the fit is poor, or the points surround the node anyway, it stays where it is.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <vector>

namespace pcskeleton {

struct RecenteringReport {
    int recentredNodes = 0;
    std::vector<int> nodes;  // the nodes moved (numbered as in the finished skeleton)
    double meanShift = 0.0;  // input units
};

// `points` are the input points in the input's frame, `skeleton.pointNode` their nodes.
// Only nodes on a bone (one or two neighbours) with enough points are considered.
RecenteringReport recentreOneSidedNodes(SkeletonGraph& skeleton, const PointList& points);

}  // namespace pcskeleton
