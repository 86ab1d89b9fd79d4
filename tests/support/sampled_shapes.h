// Point samples of shapes whose curve skeleton is known, for tests, benchmarks and demos.
// Sampling is uniform by area and deterministic for a given seed.
#pragma once

#include "pcskeleton/contraction/point_cloud_input.h"
#include "pcskeleton/skeleton/skeleton_graph.h"

#include <array>
#include <cstdint>
#include <functional>

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

struct Segment {
    Point a, b;
};
using Polyline = std::vector<Segment>;

// The surface of a tube of radius r around any set of segments (the union of capsules):
// sampled uniformly by area, points inside another segment's capsule dropped. Its curve
// skeleton is the segments themselves: branches, trees and loops made to order.
PointList tube(const Polyline& centreCurve, double radius, std::size_t n, std::uint32_t seed = 1);

// A closed regular polygon approximating the circle of radius R around `centre` in the
// z = centre.z plane.
Polyline circle(const Point& centre, double radius, int sides = 48);

// The skeleton of tube(curve, radius): one node per distinct segment end, one bone per
// segment, every radius `radius`. Segments sharing an end share its node.
SkeletonGraph curveSkeleton(const Polyline& curve, double radius);

// The points whose angle around the z axis through `centre` is outside
// [fromAngle, fromAngle + sweep) (radians): a band of missing data across a ring.
PointList withoutSector(const PointList& points, const Point& centre, double fromAngle, double sweep);

// Distance from p to the nearest segment.
double distanceToCurve(const Point& p, const Polyline& curve);

// Sheets: thin single-layer surfaces (a leaf, a plate) as seen by a scanner, given as
// triangles. A sheet has no inside; its curve skeleton, where it has one, is a mid-line.
using Triangle = std::array<Point, 3>;
using Triangles = std::vector<Triangle>;

// The image of the unit square under `map`, triangulated on a grid of cellsU x cellsV
// cells; cells whose centre (u, v) `keep` rejects are left out (holes, outlines).
Triangles sheet(const std::function<Point(double u, double v)>& map, int cellsU, int cellsV,
                const std::function<bool(double u, double v)>& keep = {});

double area(const Triangles& triangles);

// n points uniform by area on the triangles.
PointList sample(const Triangles& triangles, std::size_t n, std::uint32_t seed = 1);

// Mean distance of the points with fromZ <= z <= toZ (a surface's vertices away from its
// ends) to the wall of the cylinder of `radius` around the z axis; 1e9 if there are none.
double meanDistanceToCylinderWall(const PointList& points, double radius, double fromZ, double toZ);

}  // namespace pcskeleton::shapes
