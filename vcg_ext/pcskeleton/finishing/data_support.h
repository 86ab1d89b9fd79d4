// The invariant every finishing step keeps: a node stays with its data. A step that moves
// a node (re-centring, tip extension) checks the new position first and leaves the node
// where it was when the position would break it; the quality report counts those refusals
// and, as a last line of defence, names any node of the finished skeleton that breaks it.
//
// A node is supported by its data when
// - it lies inside the points' bounding box, grown by a share of the node spacing, and
// - its nearest own point (the nearest point at all, for a node owning none, such as an
//   extended tip) is no farther than its radius plus that share of the node spacing.
// Scale-free: radii and node spacing follow the cloud.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <memory>
#include <vector>

namespace pcskeleton {

class PointIndex;

// The share of the node spacing a node may lie beyond its radius from its nearest point,
// and beyond the bounding box.
inline constexpr double kSupportSlack = 0.5;

class DataSupport {
public:
    // `points`: the input points in the skeleton's frame (skeleton.pointNode's order); they
    // must outlive this object. `nodeSpacing` in the same units.
    DataSupport(const PointList& points, double nodeSpacing);
    ~DataSupport();
    DataSupport(const DataSupport&) = delete;
    DataSupport& operator=(const DataSupport&) = delete;

    // Whether a node at `position` with `radius`, owning `ownPoints`, stays with its data.
    bool supports(const Point& position, double radius, const std::vector<int>& ownPoints) const;

    // The nodes of `skeleton` that do not stay with their data, in increasing order.
    std::vector<int> unsupportedNodes(const SkeletonGraph& skeleton) const;

private:
    const PointList& points_;
    double slack_;
    Eigen::AlignedBox3d box_;
    std::unique_ptr<PointIndex> index_;
};

}  // namespace pcskeleton
