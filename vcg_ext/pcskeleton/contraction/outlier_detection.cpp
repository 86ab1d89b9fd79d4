#include "pcskeleton/contraction/outlier_detection.h"

#include "pcskeleton/core/errors.h"

#include "pcskeleton/internal/coordinate_sample.h"
#include "pcskeleton/internal/disjoint_sets.h"
#include "pcskeleton/internal/median.h"
#include "pcskeleton/internal/parallel_sort.h"
#include "pcskeleton/internal/spatial_index.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace pcskeleton {

namespace {

// Enough neighbours for a spacing that a single close pair or a small clump of outliers
// does not make look dense.
constexpr int kNeighbours = 8;
constexpr int kLocalPasses = 4;

struct TestedPoints {
    std::vector<char> outlier;
    double reach = 0.0;  // the isolation distance
};

// Every point's own k nearest neighbours: the isolation, local and group tests. `index` is
// made on `points`.
TestedPoints testEveryPoint(const PointList& points, const PointIndex& index, const OutlierParameters& parameters) {
    const std::size_t n = points.size();
    TestedPoints result;
    result.outlier.assign(n, 0);
    if (n < 2 * (kNeighbours + 1)) return result;
    // Everything below runs on ranks along the index's space-filling curve (see
    // spatial_index.h): each point's k nearest neighbours, row by row in one array (k + 1
    // found, the point itself first, which the row leaves out).
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
    result.reach = parameters.isolationFactor * median(kthDistance);
    std::vector<char> outlierAt(n);  // by rank
    for (std::size_t r = 0; r < n; ++r) outlierAt[r] = kthDistance[r] > result.reach;
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

    // Groups: the remaining points linked to their neighbours within result.reach.
    DisjointSets groups(n);
    for (std::size_t r = 0; r < n; ++r) {
        if (outlierAt[r]) continue;
        const Point p = index.pointAtRank(r);
        for (auto j = row(r); j != row(r + 1); ++j) {
            if (!outlierAt[*j] && (index.pointAtRank(std::size_t(*j)) - p).norm() <= result.reach) groups.unite(int(r), *j);
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
        result.outlier[order[r]] = outlierAt[r] || double(groupSize[groups.find(int(r))]) < smallest;
    }
    return result;
}

// How many of some points each cell of a grid holds. Without a usable grid (a zero or too
// small side for the box) it answers "don't know": no points in a cell, all of them around
// it, which sends every point to the exact search. The cells come from a sample and the
// queries from every point of a large cloud, in no order in space, so they are kept in one
// open-addressed array, where a lookup touches one place in memory (a node-based
// std::unordered_map touches two or three; Boost's flat maps came after the Boost that
// Debian 12 has).
class CellCounts {
public:
    CellCounts(const PointList& points, double side, const Eigen::AlignedBox3d& box)
        : origin_(box.min() - Point::Constant(side)), side_(side), total_(points.size()) {
        usable_ = side > 0.0 && (box.sizes().maxCoeff() / side) + 3.0 < double(kCellsPerAxis);
        if (!usable_) return;
        std::unordered_map<std::uint64_t, std::uint32_t> counts;
        for (const Point& p : points) ++counts[key(cell(p))];
        std::size_t capacity = 16;
        while (capacity < 2 * counts.size()) capacity *= 2;
        slots_.assign(capacity, Slot{});
        for (const auto& [cellKey, count] : counts) {
            std::size_t s = home(cellKey);
            while (slots_[s].key != kEmpty) s = (s + 1) & (capacity - 1);
            slots_[s].key = cellKey, slots_[s].count = count;
        }
    }
    // An order of the cells: row by row, layer by layer.
    std::uint64_t cellKey(const Point& p) const { return usable_ ? key(cell(p)) : 0; }
    // Whether at least `k` of the points lie within `radius` of p, counting only whole cells
    // (p's and the 26 around it) that lie within that radius: false may be wrong, true is not.
    bool surelyWithin(const Point& p, double radius, std::size_t k) const {
        if (!usable_) return false;
        const Eigen::Array3i c = cell(p);
        std::size_t count = 0;
        // p's own cell first: on a surface it often holds k points by itself.
        for (int o = 0; o < 27; ++o) {
            const Eigen::Array3i n = c + offset(o);
            const Eigen::Array3d low = origin_.array() + n.cast<double>() * side_;
            const Eigen::Array3d high = low + side_;
            const Eigen::Array3d farthest = (p.array() - low).abs().max((high - p.array()).abs());
            if (farthest.matrix().norm() <= radius && (count += countAt(n)) >= k) return true;
        }
        return false;
    }
    // The points in p's cell and the 26 around it.
    std::size_t around(const Point& p) const {
        if (!usable_) return total_;
        const Eigen::Array3i c = cell(p);
        std::size_t count = 0;
        for (int o = 0; o < 27; ++o) count += countAt(c + offset(o));
        return count;
    }

private:
    static constexpr int kCellsPerAxis = 1 << 21;
    static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);  // no cell's key: 63 bits at most
    struct Slot {
        std::uint64_t key = kEmpty;
        std::uint32_t count = 0;
    };
    // The 27 cells around a cell, its own first.
    static Eigen::Array3i offset(int o) {
        const int shifted = (o + 13) % 27;
        return Eigen::Array3i(shifted % 3 - 1, shifted / 3 % 3 - 1, shifted / 9 - 1);
    }
    Eigen::Array3i cell(const Point& p) const { return ((p - origin_) / side_).array().floor().cast<int>(); }
    static std::uint64_t key(const Eigen::Array3i& c) {
        return std::uint64_t(c[0]) | std::uint64_t(c[1]) << 21 | std::uint64_t(c[2]) << 42;
    }
    // Fibonacci hashing: neighbouring cells, whose keys differ in a few bits, land far apart.
    std::size_t home(std::uint64_t k) const { return std::size_t((k * 0x9E3779B97F4A7C15ull) >> 32) & (slots_.size() - 1); }
    const Slot* find(std::uint64_t k) const {
        for (std::size_t s = home(k);; s = (s + 1) & (slots_.size() - 1)) {
            if (slots_[s].key == k) return &slots_[s];
            if (slots_[s].key == kEmpty) return nullptr;
        }
    }
    std::size_t countAt(const Eigen::Array3i& c) const {
        const Slot* found = find(key(c));
        return found ? found->count : 0;
    }
    Point origin_;
    double side_;
    std::size_t total_;
    bool usable_ = false;
    std::vector<Slot> slots_;  // a power of two, at most half full
};

// The tests run on a uniform sample; every other point is an outlier when fewer than k of
// the sample's passing points lie within the isolation distance of it.
std::vector<char> testThroughSample(const PointList& points, const OutlierParameters& parameters) {
    const std::size_t n = points.size();
    const double share = double(parameters.statisticsSample) / double(n);
    const std::vector<char> sampled = coordinateSample(points, share);
    PointList sample;
    sample.reserve(std::size_t(1.1 * double(parameters.statisticsSample)));
    for (std::size_t i = 0; i < n; ++i) {
        if (sampled[i]) sample.push_back(points[i]);
    }
    const PointIndex sampleIndex(sample);
    const TestedPoints tested = testEveryPoint(sample, sampleIndex, parameters);
    PointList passed;
    for (std::size_t s = 0; s < sample.size(); ++s) {
        if (!tested.outlier[s]) passed.push_back(sample[s]);
    }
    std::vector<char> outlier(n, 0);
    if (passed.empty()) {
        for (std::size_t i = 0; i < n; ++i) outlier[i] = 1;
        return outlier;
    }
    // The isolation test again, against the sample: a point is isolated when fewer than k
    // passing points lie within the isolation distance. Two grids answer for most points
    // without a search: k passing points in cubes (diagonal: that distance) that lie whole
    // within that distance of the point are close enough; fewer than k in its 27 cells
    // (side: that distance) are too few. The rest, points beside the surface, count the
    // passing points among the sample's within that distance.
    const Eigen::AlignedBox3d box = boundingBox(points);
    const CellCounts cubes(passed, tested.reach / std::sqrt(3.0), box);
    const CellCounts cells(passed, tested.reach, box);
    std::size_t next = 0;  // the next point of the sample, in input order
    std::vector<std::size_t> sampleOf(n);
    for (std::size_t i = 0; i < n; ++i) sampleOf[i] = sampled[i] ? next++ : 0;
    constexpr char kUndecided = 2;
#pragma omp parallel for schedule(static)
    for (long li = 0; li < long(n); ++li) {
        const std::size_t i = std::size_t(li);
        const Point& p = points[i];
        if (sampled[i]) outlier[i] = tested.outlier[sampleOf[i]];
        else if (cubes.surelyWithin(p, tested.reach, kNeighbours)) outlier[i] = 0;
        else if (cells.around(p) < std::size_t(kNeighbours)) outlier[i] = 1;
        else outlier[i] = kUndecided;
    }
    // The searches run cell by cell: consecutive ones then touch the same part of the index.
    std::vector<std::pair<std::uint64_t, std::size_t>> undecided;
    for (std::size_t i = 0; i < n; ++i) {
        if (outlier[i] == kUndecided) undecided.emplace_back(cells.cellKey(points[i]), i);
    }
    parallelSort(undecided.begin(), undecided.end());
#pragma omp parallel
    {
        std::vector<int> found;
#pragma omp for schedule(static)
        for (long u = 0; u < long(undecided.size()); ++u) {
            const std::size_t i = undecided[std::size_t(u)].second;
            sampleIndex.withinRadius(points[i], tested.reach, found);
            const auto close = std::count_if(found.begin(), found.end(), [&](int s) {
                return !tested.outlier[std::size_t(s)] && (sample[std::size_t(s)] - points[i]).norm() <= tested.reach;
            });
            outlier[i] = close < kNeighbours;
        }
    }
    return outlier;
}

}  // namespace

void checkOutlierParameters(const OutlierParameters& p) {
    if (!(p.isolationFactor >= 1.0 && std::isfinite(p.isolationFactor)))
        throw InvalidInput(Problem::aboutParameter(Parameter::OutlierIsolation, "must be a finite number of at least 1 (typical spacings)."));
    if (!(p.localFactor >= 1.0 && std::isfinite(p.localFactor)))
        throw InvalidInput(Problem::aboutParameter(Parameter::OutlierLocalFactor, "must be a finite number of at least 1."));
    if (!(p.clusterShare >= 0.0 && p.clusterShare < 0.5))
        throw InvalidInput(Problem::aboutParameter(Parameter::OutlierClusterShare, "must be between 0 and 0.5."));
    if (p.statisticsSample < 1000) throw CallerError("OutlierParameters::statisticsSample must be at least 1000");
}

std::vector<char> findOutliers(const PointList& points, const OutlierParameters& parameters) {
    checkOutlierParameters(parameters);
    if (!parameters.detect) return std::vector<char>(points.size(), 0);
    if (points.size() > parameters.statisticsSample) return testThroughSample(points, parameters);
    const PointIndex index(points);
    return testEveryPoint(points, index, parameters).outlier;
}

}  // namespace pcskeleton
