// Distance from any point to a skeleton's bones, with the radius interpolated at the
// nearest bone point: the skeleton's cylindrical approximation of the shape (Fig. 14c),
// which Section V uses for the inside values and the outside test. CGAL's AABB tree.
#pragma once

#include "pcskeleton/skeleton/skeleton_graph.h"

#include <memory>

namespace pcskeleton {

struct SkeletonProximity {
    double distance = 0;  // to the nearest bone (or isolated node)
    double radius = 0;    // the radius there, interpolated along the bone
};

class SkeletonDistance {
public:
    // The graph must have at least one node and one radius per node.
    explicit SkeletonDistance(const SkeletonGraph& skeleton);
    ~SkeletonDistance();
    SkeletonDistance(const SkeletonDistance&) = delete;
    SkeletonDistance& operator=(const SkeletonDistance&) = delete;

    // Safe to call from several threads at once.
    SkeletonProximity nearest(const Point& p) const;

private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

}  // namespace pcskeleton
