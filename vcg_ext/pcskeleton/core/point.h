// The point type of the whole library: double precision, whatever the front end stores.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace pcskeleton {

using Point = Eigen::Vector3d;
using PointList = std::vector<Point>;

}  // namespace pcskeleton
