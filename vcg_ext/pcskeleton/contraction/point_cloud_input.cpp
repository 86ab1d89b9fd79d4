#include "pcskeleton/contraction/point_cloud_input.h"

#include "pcskeleton/internal/parallel_sort.h"
#include "pcskeleton/internal/spatial_index.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace pcskeleton {

void rejectNonFinite(const PointList& points, const std::string& what, Remedy remedy) {
    std::size_t bad = 0, first = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!points[i].allFinite()) {
            if (bad == 0) first = i;
            ++bad;
        }
    }
    if (bad > 0) {
        std::ostringstream msg;
        msg << bad << " of " << points.size() << ' ' << what
            << " have NaN or infinite coordinates (first: point " << first << ").";
        throw InvalidInput(msg.str(), {remedy});
    }
}

namespace {

void mergeExactDuplicates(const PointList& input, NormalizedCloud& cloud) {
    const ExactDuplicates duplicates = findExactDuplicates(input);
    if (!duplicates.any()) {
        cloud.points = input;
        cloud.uniqueIndex.resize(input.size());
        std::iota(cloud.uniqueIndex.begin(), cloud.uniqueIndex.end(), 0);
        return;
    }
    cloud.points = distinctPoints(input, duplicates);
    cloud.uniqueIndex = duplicates.groupOf;
}

// Removes the unique points flagged in `outlier` from `cloud.points`, keeping the others in
// order; every input point copy of an outlier is recorded, at its input position.
void setOutliersAside(const PointList& input, const std::vector<char>& outlier, NormalizedCloud& cloud) {
    if (std::find(outlier.begin(), outlier.end(), 1) == outlier.end()) return;
    std::vector<int> kept(cloud.points.size(), -1);
    PointList points;
    for (std::size_t u = 0; u < cloud.points.size(); ++u) {
        if (outlier[u]) continue;
        kept[u] = int(points.size());
        points.push_back(cloud.points[u]);
    }
    cloud.points = std::move(points);
    for (std::size_t i = 0; i < input.size(); ++i) {
        int& index = cloud.uniqueIndex[i];
        if (kept[index] >= 0) {
            index = kept[index];
        } else {
            index = -1 - int(cloud.outliers.size());
            cloud.outliers.push_back(input[i]);
        }
    }
}

void rejectCollinear(const PointList& points) {
    Point mean = Point::Zero();
    for (const Point& p : points) mean += p;
    mean /= static_cast<double>(points.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const Point& p : points) covariance += (p - mean) * (p - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    const Eigen::Vector3d& lambda = eigen.eigenvalues();  // ascending
    if (lambda(1) > 1e-12 * lambda(2)) return;
    // Off the line by more than rounding: say how far, since a cloud of parts very far apart
    // for their size (scans of separate objects in one frame) is such a line too, though
    // its points are no line to the eye. (Coordinates written in single precision are off a
    // line by as much, so the message cannot tell which.)
    constexpr double kRounding = 1e-12;
    const Point axis = eigen.eigenvectors().col(2);
    double farthest = 0.0, low = 0.0, high = 0.0;
    for (const Point& p : points) {
        const Point offset = p - mean;
        const double along = offset.dot(axis);
        low = std::min(low, along), high = std::max(high, along);
        farthest = std::max(farthest, (offset - along * axis).norm());
    }
    std::ostringstream msg;
    msg << "All points lie on one straight line";
    const bool offTheLine = high > low && farthest > kRounding * (high - low);
    if (offTheLine) msg << ", within " << std::setprecision(2) << farthest / (high - low) << " of its length";
    msg << ": such a cloud is already a curve and has no surface to contract.";
    if (offTheLine) {
        msg << " If the points are no line to the eye, the cloud holds parts very far apart for their size "
               "(separate scans in one frame?): give each part on its own.";
    }
    throw InvalidInput(msg.str());
}

// A 64-bit hash of a point's exact coordinates (-0 and +0 alike, as == sees them).
std::uint64_t exactHash(const Point& p) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int axis = 0; axis < 3; ++axis) {
        const double c = p[axis] == 0.0 ? 0.0 : p[axis];
        std::uint64_t bits;
        std::memcpy(&bits, &c, sizeof bits);
        h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        h ^= h >> 31, h *= 0xbf58476d1ce4e5b9ull, h ^= h >> 27;  // splitmix64's mixing
    }
    return h;
}

// Puts the distinct points along a Z-order curve through their bounding box, the points of
// one cell of the curve by their coordinates: an order that the positions alone fix. Every
// later step that visits points in turn (a seed, a tie, the solver's elimination order)
// then gives the same skeleton however the input lists its points, and points near in
// space are mostly near in memory.
void putInSpatialOrder(NormalizedCloud& cloud) {
    const std::size_t n = cloud.points.size();
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed = sortedZOrderCodes(cloud.points);
    for (std::size_t begin = 0, end = 0; begin < n; begin = end) {  // one cell's points by coordinates
        end = begin + 1;
        while (end < n && keyed[end].first == keyed[begin].first) ++end;
        std::sort(keyed.begin() + long(begin), keyed.begin() + long(end), [&](const auto& a, const auto& b) {
            return lexicographicallyBefore(cloud.points[a.second], cloud.points[b.second]);
        });
    }
    PointList ordered(n);
    std::vector<int> rank(n);
    for (std::size_t r = 0; r < n; ++r) {
        ordered[r] = cloud.points[keyed[r].second];
        rank[keyed[r].second] = int(r);
    }
    cloud.points = std::move(ordered);
    for (int& unique : cloud.uniqueIndex) {
        if (unique >= 0) unique = rank[std::size_t(unique)];
    }
}

}  // namespace

// Points are sorted by a hash of their coordinates (not by the coordinates themselves:
// sorting 10M indices through the points is several times slower); equal points then sit
// in one run of equal hashes, where they are told apart from collisions exactly. Groups
// are numbered by their first member, so that a cloud without duplicates keeps its order.
ExactDuplicates findExactDuplicates(const PointList& points) {
    const std::size_t n = points.size();
    std::vector<std::pair<std::uint64_t, int>> keyed(n);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < long(n); ++i) keyed[std::size_t(i)] = {exactHash(points[std::size_t(i)]), int(i)};
    // By hash, then index: the same on every run and any number of threads.
    parallelSort(keyed.begin(), keyed.end());

    ExactDuplicates duplicates;
    std::vector<int> distinctInRun;  // the first member of each distinct point of a run
    for (std::size_t begin = 0, end = 0; begin < n; begin = end) {
        end = begin + 1;
        while (end < n && keyed[end].first == keyed[begin].first) ++end;
        if (end - begin == 1) continue;
        distinctInRun.clear();
        for (std::size_t r = begin; r < end; ++r) {
            const int i = keyed[r].second;
            const auto same = std::find_if(distinctInRun.begin(), distinctInRun.end(),
                                           [&](int first) { return points[std::size_t(first)] == points[std::size_t(i)]; });
            if (same == distinctInRun.end()) {
                distinctInRun.push_back(i);
                continue;
            }
            if (!duplicates.any()) {  // the first repeat: every point its own leader so far
                duplicates.groupOf.resize(n);
                std::iota(duplicates.groupOf.begin(), duplicates.groupOf.end(), 0);
            }
            duplicates.groupOf[std::size_t(i)] = *same;  // members come in index order: *same is the smallest
        }
    }
    if (!duplicates.any()) return duplicates;
    keyed.clear();
    keyed.shrink_to_fit();
    // Leaders come before their group's other members: one pass numbers the groups.
    std::vector<int>& groupOf = duplicates.groupOf;
    for (std::size_t i = 0; i < n; ++i) {
        const int leader = groupOf[i];
        if (leader == int(i)) {
            groupOf[i] = int(duplicates.firstOf.size());
            duplicates.firstOf.push_back(int(i));
        } else {
            groupOf[i] = groupOf[std::size_t(leader)];
        }
    }
    return duplicates;
}

PointList distinctPoints(const PointList& points, const ExactDuplicates& duplicates) {
    PointList distinct;
    distinct.reserve(duplicates.firstOf.size());
    for (int first : duplicates.firstOf) distinct.push_back(points[std::size_t(first)]);
    return distinct;
}

void rejectUnrepresentableScale(const PointList& points, const std::string& what) {
    // Squared coordinates and squared differences stay between these bounds (with room
    // for sums of a few thousand of them and for ratios of lengths).
    constexpr double kLargest = 1e100, kSmallestExtent = 1e-100;
    const Eigen::AlignedBox3d box = boundingBox(points);
    if (box.isEmpty()) return;
    const double largest = std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
    const double extent = box.sizes().maxCoeff();
    std::ostringstream msg;
    msg.precision(3);
    if (largest > kLargest) {
        msg << "The " << what << " have coordinates up to " << largest << ", beyond the " << kLargest
            << " within which squared distances can be computed: scale the cloud down.";
        throw InvalidInput(msg.str());
    }
    if (extent > 0 && extent < kSmallestExtent) {
        msg << "The " << what << " span only " << extent << ", below the " << kSmallestExtent
            << " down to which squared distances can be told apart: scale the cloud up.";
        throw InvalidInput(msg.str());
    }
}

NormalizedCloud normalizeCloud(const PointList& input, std::size_t minimumUniquePoints,
                               const OutlierParameters& outliers) {
    if (input.empty()) throw InvalidInput("The cloud is empty: it has no points.");
    rejectNonFinite(input, "points", Remedy::take(Step::RemoveNonFinitePoints));
    rejectUnrepresentableScale(input, "points");

    NormalizedCloud cloud;
    mergeExactDuplicates(input, cloud);
    const std::size_t distinct = cloud.points.size();
    setOutliersAside(input, findOutliers(cloud.points, outliers), cloud);
    if (cloud.points.size() < minimumUniquePoints) {
        std::ostringstream msg;
        msg << "Too few points: " << cloud.points.size() << " distinct points";
        if (distinct != input.size()) msg << " (" << input.size() << " with duplicates)";
        if (!cloud.outliers.empty()) msg << " besides " << cloud.outliers.size() << " outliers";
        msg << ", at least " << minimumUniquePoints << " are needed (k nearest neighbours + 1).";
        std::vector<Remedy> remedies{Remedy::lower(Parameter::NeighbourCount)};
        if (!cloud.outliers.empty()) remedies.push_back(Remedy::raise(Parameter::OutlierIsolation));
        throw InvalidInput(msg.str(), remedies);
    }

    const Eigen::AlignedBox3d box = boundingBox(cloud.points);
    cloud.center = box.center();
    cloud.scale = kNormalizedLongestSide / box.sizes().maxCoeff();
    cloud.diagonal = box.diagonal().norm() * cloud.scale;
    for (Point& p : cloud.points) p = (p - cloud.center) * cloud.scale;
    putInSpatialOrder(cloud);

    rejectCollinear(cloud.points);
    return cloud;
}

}  // namespace pcskeleton
