// Point samples of shapes whose curve skeleton is known, for tests, benchmarks and demos.
// Sampling is uniform by area and deterministic for a given seed.
#pragma once

#include "pcskeleton/point_cloud_input.h"

#include <cstdint>

namespace pcskeleton::shapes {

// Tube of radius r around the z axis from z = 0 to z = length, closed with hemispheres
// when `capped`. Skeleton: the axis segment.
PointList cylinder(std::size_t n, double radius, double length, bool capped, std::uint32_t seed = 1);

// Torus around the z axis with centre-line radius R and tube radius r.
// Skeleton: the circle of radius R in the z = 0 plane.
PointList torus(std::size_t n, double majorRadius, double minorRadius, std::uint32_t seed = 1);

// Sphere of radius r at the origin. Skeleton: its centre.
PointList sphere(std::size_t n, double radius, std::uint32_t seed = 1);

// Distance from p to the segment [a, b].
double distanceToSegment(const Point& p, const Point& a, const Point& b);

}  // namespace pcskeleton::shapes
