#include "pcskeleton/contraction/point_subsampling.h"

#include "pcskeleton/core/errors.h"
#include "pcskeleton/internal/coordinate_sample.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace pcskeleton {

namespace {

// Counting occupied cubes on every point of a 10M-point scan, a dozen times over, would
// cost more than the contraction it saves; a sample with this many points per target cube
// (chosen by coordinates, so that it does not depend on the input's order) finds the cube
// size nearly as well, and the final grid uses every point.
constexpr std::size_t kSearchPointsPerCube = 50;
// Bisection steps on the logarithm of the cube size: the bracket spans the sizes of a
// curve-like and of a volume-filling cloud, and 12 halvings bring it within about 2%.
constexpr int kSearchSteps = 12;

class Grid {
public:
    Grid(const Point& origin, double cellSize) : origin_(origin), inverse_(1.0 / cellSize) {}

    // 21 bits per axis: a box of up to two million cubes on a side.
    std::uint64_t key(const Point& p) const {
        const Eigen::Array3d cell = ((p - origin_) * inverse_).array().floor();
        const auto bits = [](double c) { return std::uint64_t(std::min(c, double((1 << 21) - 1))); };
        return bits(cell[0]) | bits(cell[1]) << 21 | bits(cell[2]) << 42;
    }

private:
    Point origin_;
    double inverse_;
};

std::size_t occupiedCubes(const PointList& points, const std::vector<int>& sample, const Grid& grid,
                          std::size_t stopAbove) {
    std::unordered_set<std::uint64_t> cubes;
    cubes.reserve(2 * stopAbove);
    for (const int i : sample) {
        cubes.insert(grid.key(points[std::size_t(i)]));
        if (cubes.size() > stopAbove) break;  // too fine already
    }
    return cubes.size();
}

}  // namespace

PointSubsample spreadSubsample(const PointList& points, std::size_t target, const std::vector<char>& leaveOut) {
    if (target == 0) throw CallerError("spreadSubsample: the target must be at least 1");
    if (!leaveOut.empty() && leaveOut.size() != points.size()) throw CallerError("spreadSubsample: one flag per point");
    std::vector<int> used;  // the points not left out
    used.reserve(points.size());
    Eigen::AlignedBox3d box;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!leaveOut.empty() && leaveOut[i]) continue;
        used.push_back(int(i));
        box.extend(points[i]);
    }
    PointSubsample result;
    result.keeperOf.assign(points.size(), -1);
    const double diagonal = used.empty() ? 0.0 : box.diagonal().norm();
    if (used.size() <= target || !(diagonal > 0.0)) {
        result.kept = used;
        for (std::size_t u = 0; u < used.size(); ++u) result.keeperOf[used[u]] = int(u);
        return result;
    }
    // Cubes needed to hold `target` cells: diagonal / target (points on a curve) up to
    // diagonal / cbrt(target) (points filling the box); the margin keeps the coarse end
    // safely under the target.
    const std::size_t stride = std::max<std::size_t>(1, used.size() / (kSearchPointsPerCube * target));
    std::vector<int> sample;  // about one in `stride` of the used points
    if (stride > 1) {
        const std::vector<char> sampled = coordinateSample(points, 1.0 / double(stride));
        for (const int i : used) {
            if (sampled[std::size_t(i)]) sample.push_back(i);
        }
    }
    const std::vector<int>& searched = stride > 1 ? sample : used;
    const Point origin = box.min();
    double fine = std::log(diagonal / double(target)), coarse = std::log(2.0 * diagonal / std::cbrt(double(target)));
    for (int step = 0; step < kSearchSteps; ++step) {
        const double middle = 0.5 * (fine + coarse);
        if (occupiedCubes(points, searched, Grid(origin, std::exp(middle)), target) > target) fine = middle;
        else coarse = middle;
    }
    // Each cube keeps its point nearest to the cube's centroid: a real sample, in the middle,
    // whatever the order of the input (a random point of each cube measured no better:
    // docs/benchmarks.md#measurements-behind-the-constants). The sample misses some
    // sparse cubes: the cube grows until all points fit, and the pass they fit in is kept.
    double cellSize = std::exp(coarse);
    std::unordered_map<std::uint64_t, int> cubeOf;
    cubeOf.reserve(2 * target);
    std::vector<int> cubeOfUsed(used.size());
    PointList centroid;
    std::vector<int> members;
    for (;;) {
        const Grid grid(origin, cellSize);
        cubeOf.clear(), centroid.clear(), members.clear();
        bool fits = true;
        for (std::size_t u = 0; u < used.size() && fits; ++u) {
            const Point& p = points[used[u]];
            const auto [entry, added] = cubeOf.try_emplace(grid.key(p), int(centroid.size()));
            if (added) centroid.push_back(Point::Zero()), members.push_back(0);
            cubeOfUsed[u] = entry->second;
            centroid[entry->second] += p;
            ++members[entry->second];
            fits = centroid.size() <= target;
        }
        if (fits) break;
        cellSize *= 1.05;
    }
    result.cellSize = cellSize;
    std::vector<int> nearest(centroid.size(), -1);
    std::vector<double> nearestDistance(centroid.size(), std::numeric_limits<double>::infinity());
    for (std::size_t c = 0; c < centroid.size(); ++c) centroid[c] /= double(members[c]);
    for (std::size_t u = 0; u < used.size(); ++u) {
        const int c = cubeOfUsed[u];
        const Point& p = points[std::size_t(used[u])];
        const double d = (p - centroid[c]).squaredNorm();
        // Equally near points (a regular grid's) by coordinates, not by their order.
        if (d < nearestDistance[c] ||
            (d == nearestDistance[c] && lexicographicallyBefore(p, points[std::size_t(nearest[c])]))) {
            nearestDistance[c] = d, nearest[c] = used[u];
        }
    }
    // Kept points in input order, so the subsample does not depend on hashing.
    std::vector<int> order(nearest.size());
    for (std::size_t c = 0; c < order.size(); ++c) order[c] = int(c);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return nearest[a] < nearest[b]; });
    std::vector<int> rank(order.size());
    for (std::size_t r = 0; r < order.size(); ++r) rank[order[r]] = int(r), result.kept.push_back(nearest[order[r]]);
    for (std::size_t u = 0; u < used.size(); ++u) result.keeperOf[used[u]] = rank[cubeOfUsed[u]];
    return result;
}

PointList keptPoints(const PointList& points, const PointSubsample& subsample) {
    PointList kept;
    kept.reserve(subsample.kept.size());
    for (int i : subsample.kept) kept.push_back(points[i]);
    return kept;
}

}  // namespace pcskeleton
