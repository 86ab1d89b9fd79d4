// Checks a raw point cloud and puts it in the frame the algorithm works in.
#pragma once

#include "pcskeleton/core/errors.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace pcskeleton {

using Point = Eigen::Vector3d;
using PointList = std::vector<Point>;

// The cloud as the algorithm sees it: exact duplicates merged, centred on its bounding
// box and scaled so that the longest side of the box is 1.6 (the frame of the authors'
// reference code, in which the paper's default weights were tuned). Results are mapped
// back with toInputFrame(), so every result is independent of the cloud's units.
struct NormalizedCloud {
    PointList points;              // unique points, normalised frame
    std::vector<int> uniqueIndex;  // for each input point, its index in `points`
    Point center = Point::Zero();
    double scale = 1.0;            // normalised = (input - center) * scale
    double diagonal = 0.0;         // bounding-box diagonal, normalised frame

    Point toInputFrame(const Point& p) const { return p / scale + center; }
    Point toNormalizedFrame(const Point& p) const { return (p - center) * scale; }
    std::size_t inputSize() const { return uniqueIndex.size(); }
};

constexpr double kNormalizedLongestSide = 1.6;

// The axis-aligned box holding the points (empty for no points).
Eigen::AlignedBox3d boundingBox(const PointList& points);

// Validates and normalises. Throws InvalidInput, naming the problem and what to do,
// for: no points; NaN or infinite coordinates; fewer than `minimumUniquePoints`
// distinct points; all points (numerically) on one line.
NormalizedCloud normalizeCloud(const PointList& input, std::size_t minimumUniquePoints);

// Throws InvalidInput when a point has a NaN or infinite coordinate, naming how many and
// the first: "<count> of <n> <what> have NaN or infinite coordinates (first: point i).",
// with `remedy`.
void rejectNonFinite(const PointList& points, const std::string& what, Remedy remedy);

}  // namespace pcskeleton
