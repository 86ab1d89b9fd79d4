// Nodes of one-sided data moved to the centre of their cross-section. Where a node's
// points cover only part of the cross-section around its bone (a scan from one side, a
// hole), the centre of its points, where the paper's embedding puts it, lies on the
// visible wall. Such a node moves to the centre of the circle that fits its points in the
// plane across the bone (an algebraic least-squares fit), and takes that circle's radius;
// when the fit is poor, or the points surround the node anyway, it stays where it is. So does
// a node whose neighbours do not show a tube: a tube's radius changes slowly along its bone,
// so a neighbour's circle agrees with the node's (or the neighbour's points surround it),
// while the circle fitted across a curled sheet (a leaf) follows the curl. A leaf folded along
// its midrib fits a circle too, but its two wings are nearly straight: a tube's wall curves
// as evenly in each half of its arc as in the whole.
#pragma once

#include "pcskeleton/finishing/data_support.h"
#include "pcskeleton/skeleton/skeleton_graph.h"

#include <vector>

namespace pcskeleton {

struct RecenteringReport {
    int recentredNodes = 0;
    std::vector<int> nodes;  // the nodes moved (numbered as in the finished skeleton)
    double meanShift = 0.0;  // input units
    int refused = 0;         // moves that would have taken a node away from its data (data_support.h)
    int unlikeNeighbours = 0;  // nodes left in place: their neighbours do not show a tube (a curled leaf)
    int foldedSheets = 0;      // nodes left in place: their arc does not curve evenly (a leaf folded along its midrib)
};

// `points` are the input points in the input's frame, `skeleton.pointNode` their nodes.
// Only nodes on a bone (one or two neighbours) with enough points are considered, and a
// node moves only where it stays with its data (`support`, made on the same points).
RecenteringReport recentreOneSidedNodes(SkeletonGraph& skeleton, const PointList& points, const DataSupport& support);

}  // namespace pcskeleton
