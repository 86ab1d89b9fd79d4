#include "pcskeleton/contraction/outlier_detection.h"

#include "pcskeleton/core/errors.h"

#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/internal/median.h"
#include "pcskeleton/internal/spatial_index.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pcskeleton {

namespace {

// Enough neighbours for a spacing that a single close pair or a small clump of outliers
// does not make look dense.
constexpr int kNeighbours = 8;
constexpr int kLocalPasses = 4;

}  // namespace

void checkOutlierParameters(const OutlierParameters& p) {
    if (!(p.isolationFactor >= 1.0 && std::isfinite(p.isolationFactor)))
        throw InvalidInput(Problem::aboutParameter(Parameter::OutlierIsolation, "must be a finite number of at least 1 (typical spacings)."));
    if (!(p.localFactor >= 1.0 && std::isfinite(p.localFactor)))
        throw InvalidInput(Problem::aboutParameter(Parameter::OutlierLocalFactor, "must be a finite number of at least 1."));
    if (!(p.clusterShare >= 0.0 && p.clusterShare < 0.5))
        throw InvalidInput(Problem::aboutParameter(Parameter::OutlierClusterShare, "must be between 0 and 0.5."));
}

std::vector<char> findOutliers(const PointList& points, const OutlierParameters& parameters) {
    checkOutlierParameters(parameters);
    const std::size_t n = points.size();
    std::vector<char> outlier(n, 0);
    if (!parameters.detect || n < 2 * (kNeighbours + 1)) return outlier;

    // Everything below runs on ranks along the index's space-filling curve (see
    // spatial_index.h): each point's k nearest neighbours, row by row in one array (k + 1
    // found, the point itself first, which the row leaves out).
    const PointIndex index(points);
    std::vector<int> neighbours(n * kNeighbours);
    auto row = [&](std::size_t r) { return neighbours.begin() + std::ptrdiff_t(r * kNeighbours); };
    std::vector<double> kthDistance(n);
#pragma omp parallel
    {
        std::vector<int> found;
#pragma omp for schedule(static)
        for (long r = 0; r < long(n); ++r) {
            const Point p = index.pointAtRank(std::size_t(r));
            index.nearestRanks(p, kNeighbours + 1, found);
            // The point itself is first, unless exact duplicates of it came first.
            const auto self = std::find(found.begin(), found.end(), int(r));
            found.erase(self != found.end() ? self : found.end() - 1);
            std::copy(found.begin(), found.begin() + kNeighbours, row(std::size_t(r)));
            kthDistance[std::size_t(r)] = (index.pointAtRank(std::size_t(found[kNeighbours - 1])) - p).norm();
        }
    }
    const double reach = parameters.isolationFactor * median(kthDistance);
    std::vector<char> outlierAt(n);  // by rank
    for (std::size_t r = 0; r < n; ++r) outlierAt[r] = kthDistance[r] > reach;
    // The local test compares with the upper quartile of the neighbours' spacing: high
    // enough that the sparse side of a change in density is not taken for outliers, low
    // enough that two outliers side by side do not hide each other. Repeated without the
    // neighbours found so far, which hid the outliers beside them.
    for (int pass = 0; pass < kLocalPasses; ++pass) {
        std::vector<char> found = outlierAt;
#pragma omp parallel for schedule(static)
        for (long r = 0; r < long(n); ++r) {
            std::array<double, kNeighbours> around;
            std::size_t count = 0;
            for (auto j = row(std::size_t(r)); j != row(std::size_t(r) + 1); ++j) {
                if (!outlierAt[*j]) around[count++] = kthDistance[*j];
            }
            if (count == 0) continue;
            const auto quartile = around.begin() + std::ptrdiff_t(3 * count / 4);
            std::nth_element(around.begin(), quartile, around.begin() + std::ptrdiff_t(count));
            if (kthDistance[r] > parameters.localFactor * *quartile) found[r] = 1;
        }
        if (found == outlierAt) break;
        outlierAt = std::move(found);
    }

    // Groups: the remaining points linked to their neighbours within reach.
    DisjointSets groups(n);
    for (std::size_t r = 0; r < n; ++r) {
        if (outlierAt[r]) continue;
        const Point p = index.pointAtRank(r);
        for (auto j = row(r); j != row(r + 1); ++j) {
            if (!outlierAt[*j] && (index.pointAtRank(std::size_t(*j)) - p).norm() <= reach) groups.unite(int(r), *j);
        }
    }
    std::vector<std::size_t> groupSize(n, 0);
    std::size_t kept = 0;
    for (std::size_t r = 0; r < n; ++r) {
        if (!outlierAt[r]) ++groupSize[groups.find(int(r))], ++kept;
    }
    const double smallest = parameters.clusterShare * double(kept);
    const std::vector<std::size_t>& order = index.spatialOrder();
    for (std::size_t r = 0; r < n; ++r) {
        outlier[order[r]] = outlierAt[r] || double(groupSize[groups.find(int(r))]) < smallest;
    }
    return outlier;
}

}  // namespace pcskeleton
