// What real acquisition does to a sampled surface, made to order and deterministic for a
// given seed: noise, outliers, uneven density, the views of a scanner, misregistered
// scans. For the robustness suite (bench_robustness) and the tests.
#pragma once

#include "pcskeleton/contraction/point_cloud_input.h"

#include <cstdint>

namespace pcskeleton::shapes {

// Moves every point by Gaussian noise whose standard deviation, per coordinate, is
// `share` of the bounding-box diagonal.
PointList withNoise(const PointList& points, double share, std::uint32_t seed = 1);

// Adds share x n points drawn uniformly in the bounding box grown by 10% on each side.
PointList withOutliers(const PointList& points, double share, std::uint32_t seed = 1);

// `n` points of which half lie in `areaShare` of the surface (the points of `dense`
// nearest to one of them, chosen by the seed) and half elsewhere. `dense` must be a
// uniform sample with at least n / (2 areaShare) points.
PointList unevenlyDense(const PointList& dense, std::size_t n, double areaShare, std::uint32_t seed = 1);

// The points a scanner looking along `direction` sees: an orthographic depth buffer of
// square pixels (`pixel` wide) keeps, per pixel, the points within two pixels of the
// nearest depth. Pixels should be about three sample spacings wide: an empty pixel
// lets the back show through.
PointList visibleFrom(const PointList& dense, const Point& direction, double pixel);

// The union of what `views` scanners evenly spread around the z axis (tilted 30 degrees
// down) see, without repeats.
PointList virtualScans(const PointList& dense, int views, double pixel);

// `views` scans as above, each moved by a random rigid motion: a rotation about the
// cloud's centre and a translation, each displacing points by about `share` of the
// bounding-box diagonal (the paper's Fig. 9 experiment).
PointList misalignedScans(const PointList& dense, int views, double pixel, double share, std::uint32_t seed = 1);

}  // namespace pcskeleton::shapes
