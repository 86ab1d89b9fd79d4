// The point type of the whole library: double precision, whatever the front end stores.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <vector>

namespace pcskeleton {

using Point = Eigen::Vector3d;
using PointList = std::vector<Point>;

// The axis-aligned box holding the points (empty for no points).
inline Eigen::AlignedBox3d boundingBox(const PointList& points) {
    Eigen::AlignedBox3d box;
    for (const Point& p : points) box.extend(p);
    return box;
}

// Points by their coordinates, x first: an order that depends on where points are, not on
// how a file lists them (for ties and seeds).
inline bool lexicographicallyBefore(const Point& p, const Point& q) {
    return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
}

}  // namespace pcskeleton
