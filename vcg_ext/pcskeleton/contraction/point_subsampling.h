// The multi-resolution pipeline's subsample (not in the paper): a large scan is contracted
// through a well-spread subset of its points, and every input point then takes the node
// of the subset point that stands for it.
//
// The subset is a voxel grid: the cloud's bounding box is cut into cubes, and each cube
// that holds points keeps the one nearest to their centroid. The cube size is chosen so
// that at most `target` cubes are occupied. A grid spreads the kept points evenly over the
// surface, whatever the scanner's density: dense patches lose the most, and a thin part
// keeps as many points as its surface area at that spacing (a Poisson-disk sample would
// do the same, at a cost that grows faster with the cloud). Unlike CGAL's
// grid_simplify_point_set, which keeps one point per cell too, it tells which kept point
// stands for each removed one: the correspondence needs that.
#pragma once

#include "pcskeleton/core/point.h"

#include <cstddef>
#include <vector>

namespace pcskeleton {

struct PointSubsample {
    std::vector<int> kept;      // indices of the kept points, ascending
    std::vector<int> keeperOf;  // per input point: the index into `kept` of the point standing for it, -1 if left out
    double cellSize = 0.0;      // the cubes' side, input units
};

// The grid subsample of `points` with at most `target` kept points (target >= 1) and, among
// the cube sizes tried, the smallest giving that. Points i with leaveOut[i] != 0 (e.g.
// outliers; empty = none) are neither kept nor stood for. Deterministic. `points` must be
// finite.
PointSubsample spreadSubsample(const PointList& points, std::size_t target, const std::vector<char>& leaveOut = {});

// The kept points themselves, in `kept` order.
PointList keptPoints(const PointList& points, const PointSubsample& subsample);

}  // namespace pcskeleton
