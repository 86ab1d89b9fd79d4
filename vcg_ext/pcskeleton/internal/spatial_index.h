// Radius queries on a fixed point list (CGAL's kd-tree), for the steps that need them
// after the 1-rings (sampling the contracted points).
#pragma once

#include "pcskeleton/core/point_cloud_input.h"

#include <memory>
#include <vector>

namespace pcskeleton {

class PointIndex {
public:
    // `points` must outlive the index and must not change while it exists.
    explicit PointIndex(const PointList& points);
    ~PointIndex();
    PointIndex(const PointIndex&) = delete;
    PointIndex& operator=(const PointIndex&) = delete;

    // Replaces `found` with the indices of the points within `radius` of `centre`.
    void withinRadius(const Point& centre, double radius, std::vector<int>& found) const;

private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

}  // namespace pcskeleton
