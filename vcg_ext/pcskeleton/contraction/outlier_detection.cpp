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

    // Each point's k nearest neighbours, row by row in one array (k + 1 found, the point
    // itself first, which the row leaves out).
    const PointIndex index(points);
    std::vector<int> neighbours(n * kNeighbours);
    auto row = [&](std::size_t i) { return neighbours.begin() + std::ptrdiff_t(i * kNeighbours); };
    std::vector<double> kthDistance(n);
    const std::vector<std::size_t>& order = index.spatialOrder();
#pragma omp parallel
    {
        std::vector<int> found;
#pragma omp for schedule(static)
        for (long r = 0; r < long(n); ++r) {
            const std::size_t i = order[std::size_t(r)];
            index.nearest(points[i], kNeighbours + 1, found);
            std::copy(found.begin() + 1, found.end(), row(i));
            kthDistance[i] = (points[found.back()] - points[i]).norm();
        }
    }
    const double reach = parameters.isolationFactor * median(kthDistance);
    for (std::size_t i = 0; i < n; ++i) outlier[i] = kthDistance[i] > reach;
    // The local test compares with the upper quartile of the neighbours' spacing: high
    // enough that the sparse side of a change in density is not taken for outliers, low
    // enough that two outliers side by side do not hide each other. Repeated without the
    // neighbours found so far, which hid the outliers beside them.
    for (int pass = 0; pass < kLocalPasses; ++pass) {
        std::vector<char> found = outlier;
#pragma omp parallel for schedule(static)
        for (long i = 0; i < long(n); ++i) {
            std::array<double, kNeighbours> around;
            std::size_t count = 0;
            for (auto j = row(std::size_t(i)); j != row(std::size_t(i) + 1); ++j) {
                if (!outlier[*j]) around[count++] = kthDistance[*j];
            }
            if (count == 0) continue;
            const auto quartile = around.begin() + std::ptrdiff_t(3 * count / 4);
            std::nth_element(around.begin(), quartile, around.begin() + std::ptrdiff_t(count));
            if (kthDistance[i] > parameters.localFactor * *quartile) found[i] = 1;
        }
        if (found == outlier) break;
        outlier = std::move(found);
    }

    // Groups: the remaining points linked to their neighbours within reach.
    DisjointSets groups(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (outlier[i]) continue;
        for (auto j = row(i); j != row(i + 1); ++j) {
            if (!outlier[*j] && (points[*j] - points[i]).norm() <= reach) groups.unite(int(i), *j);
        }
    }
    std::vector<std::size_t> groupSize(n, 0);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!outlier[i]) ++groupSize[groups.find(int(i))], ++kept;
    }
    const double smallest = parameters.clusterShare * double(kept);
    for (std::size_t i = 0; i < n; ++i) {
        if (!outlier[i] && double(groupSize[groups.find(int(i))]) < smallest) outlier[i] = 1;
    }
    return outlier;
}

}  // namespace pcskeleton
