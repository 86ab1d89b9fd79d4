// The point type of the whole library: double precision, whatever the front end stores.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

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

}  // namespace pcskeleton
