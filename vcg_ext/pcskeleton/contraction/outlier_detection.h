// Points that do not belong to the sampled surface: isolated points and small sparse
// clusters (stray returns, dust, a few points of a background object). The paper has no
// such step; on real scans one outlier among a surface point's neighbours drags that point
// out during contraction and leaves a false loop. Scale-free: every length is a multiple
// of the cloud's own typical spacing, so no threshold depends on units or density.
#pragma once

#include "pcskeleton/core/point.h"

#include <vector>

namespace pcskeleton {

struct OutlierParameters {
    bool detect = true;  // false keeps every point, as the paper does
    // A point whose k-th nearest neighbour (k = 8) is farther than this many typical
    // spacings (the median of that distance over the cloud) is isolated.
    double isolationFactor = 4.0;
    // A point whose k-th nearest neighbour is farther than this many times the same distance
    // of its own neighbours (their upper quartile) stands off the surface they sample: this finds
    // the outliers close to the surface, which the isolation test misses, while a sparsely
    // sampled part (whose neighbours are as sparse) stays.
    double localFactor = 2.0;
    // Points linked to their neighbours within that distance form groups; a group holding
    // less than this share of the cloud is an outlier cluster.
    double clusterShare = 0.01;
    // Above this many points the tests run on a uniform sample of about this many, and each
    // other point is an outlier when fewer than k points of the sample that passed lie
    // within the sample's isolation distance. The tests ask how far a point stands from the surface
    // relative to the cloud's spacing, which a sample of millions of points shows as the
    // whole cloud does, at a fraction of the neighbour searches. What it gives up: outliers
    // closer to the surface than the sample's isolation distance are kept (they are far
    // below the contraction's own spacing). A speed setting for library callers, not in
    // the parameter table; at least 1000.
    std::size_t statisticsSample = 2'000'000;
};

// Throws InvalidInput naming the first unusable parameter.
void checkOutlierParameters(const OutlierParameters& parameters);

// For each point, 1 if it is an outlier. Nothing is flagged when `detect` is off or the
// cloud is too small to have statistics (fewer than 2 (k + 1) points).
std::vector<char> findOutliers(const PointList& points, const OutlierParameters& parameters);

}  // namespace pcskeleton
