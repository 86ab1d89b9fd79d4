// Checks a raw point cloud and puts it in the frame the algorithm works in.
#pragma once

#include "pcskeleton/core/errors.h"
#include "pcskeleton/contraction/outlier_detection.h"
#include "pcskeleton/core/point.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace pcskeleton {


// The cloud as the algorithm sees it: exact duplicates merged, centred on its bounding
// box and scaled so that the longest side of the box is 1.6 (the frame of the authors'
// reference code, in which the paper's default weights were tuned). Results are mapped
// back with toInputFrame(), so every result is independent of the cloud's units. The
// points are in an order fixed by their positions (a Z-order curve), so every result is
// independent of the order in which the input lists them, too.
struct NormalizedCloud {
    PointList points;              // unique points that are not outliers, normalised frame, in spatial order
    // For each input point, its index in `points`; for an outlier, -1 - its index in `outliers`.
    std::vector<int> uniqueIndex;
    PointList outliers;            // the input positions of the points set aside as outliers
    Point center = Point::Zero();
    double scale = 1.0;            // normalised = (input - center) * scale
    double diagonal = 0.0;         // bounding-box diagonal, normalised frame

    Point toInputFrame(const Point& p) const { return p / scale + center; }
    Point toNormalizedFrame(const Point& p) const { return (p - center) * scale; }
    std::size_t inputSize() const { return uniqueIndex.size(); }
    bool isOutlier(std::size_t i) const { return uniqueIndex[i] < 0; }
    // Input point i where it is: from `points` (mapped back), or as it was for an outlier.
    Point inputPosition(std::size_t i) const {
        return uniqueIndex[i] >= 0 ? toInputFrame(points[uniqueIndex[i]]) : outliers[std::size_t(-1 - uniqueIndex[i])];
    }
};

constexpr double kNormalizedLongestSide = 1.6;

// Exact duplicates (scanners and merged scans repeat points bit for bit): every test that
// counts neighbours must see each position once, or a point repeated k times has only
// itself as its k neighbours.
struct ExactDuplicates {
    std::vector<int> groupOf;  // per point: its group, numbered by first appearance; empty when no point repeats
    std::vector<int> firstOf;  // per group: its first point; empty when no point repeats
    bool any() const { return !groupOf.empty(); }
};
ExactDuplicates findExactDuplicates(const PointList& points);
// Each group's position once, in group order (call only when duplicates.any()).
PointList distinctPoints(const PointList& points, const ExactDuplicates& duplicates);

// Throws InvalidInput when the cloud's extent or position cannot be worked in: squared
// distances of its coordinates must be representable as doubles (no overflow to infinity,
// no underflow to zero).
void rejectUnrepresentableScale(const PointList& points, const std::string& what);

// Validates, sets outliers aside (see outlier_detection.h) and normalises the rest (so the
// frame, and every length relative to it, follows the surface, not the outliers). Throws
// InvalidInput, naming the problem and what to do, for: no points; NaN or infinite
// coordinates; fewer than `minimumUniquePoints` distinct points that are not outliers; all
// those points (numerically) on one line.
NormalizedCloud normalizeCloud(const PointList& input, std::size_t minimumUniquePoints,
                               const OutlierParameters& outliers);

// Throws InvalidInput when a point has a NaN or infinite coordinate, naming how many and
// the first: "<count> of <n> <what> have NaN or infinite coordinates (first: point i).",
// with `remedy`.
void rejectNonFinite(const PointList& points, const std::string& what, Remedy remedy);

}  // namespace pcskeleton
