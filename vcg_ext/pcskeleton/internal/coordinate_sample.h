// A pseudo-random sample of a cloud chosen from each point's coordinates alone: the same
// points whatever the order of the points in the file, where every n-th point of the
// input would depend on it. The outlier tests and the subsample's search for its cube
// size run on such samples.
#pragma once

#include "pcskeleton/core/point.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace pcskeleton {

// The threshold that keeps about `share` (0 to 1) of the points.
inline std::uint64_t coordinateSampleThreshold(double share) {
    return std::uint64_t(share * 18446744073709551615.0);
}

inline bool inCoordinateSample(const Point& p, std::uint64_t threshold) {
    std::uint64_t h = 0;
    for (int axis = 0; axis < 3; ++axis) {
        std::uint64_t bits;
        const double c = p[axis];
        std::memcpy(&bits, &c, sizeof bits);
        h = (h ^ bits) * 0x9e3779b97f4a7c15ULL;
        h ^= h >> 29;
    }
    h *= 0xbf58476d1ce4e5b9ULL;
    return (h ^ (h >> 32)) < threshold;
}

// Per point, whether it is in the sample of about `share` (0 to 1) of the points.
inline std::vector<char> coordinateSample(const PointList& points, double share) {
    const std::uint64_t threshold = coordinateSampleThreshold(share);
    std::vector<char> sampled(points.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < long(points.size()); ++i) {
        sampled[std::size_t(i)] = inCoordinateSample(points[std::size_t(i)], threshold);
    }
    return sampled;
}

}  // namespace pcskeleton
