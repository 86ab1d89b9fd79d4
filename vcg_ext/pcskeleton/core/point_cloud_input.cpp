#include "pcskeleton/core/point_cloud_input.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
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

// Sorting indices lexicographically groups exact duplicates; each group keeps the
// position of its first member.
void mergeExactDuplicates(const PointList& input, NormalizedCloud& cloud) {
    std::vector<int> order(input.size());
    std::iota(order.begin(), order.end(), 0);
    auto less = [&](int a, int b) {
        const Point& p = input[a];
        const Point& q = input[b];
        if (p.x() != q.x()) return p.x() < q.x();
        if (p.y() != q.y()) return p.y() < q.y();
        if (p.z() != q.z()) return p.z() < q.z();
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);

    // Unique points are numbered in input order so that a cloud without duplicates
    // keeps its order (uniqueIndex is then the identity).
    std::vector<int> groupLeader(input.size());
    for (std::size_t s = 0; s < order.size(); ++s) {
        bool sameAsPrevious = s > 0 && input[order[s]] == input[order[s - 1]];
        groupLeader[order[s]] = sameAsPrevious ? groupLeader[order[s - 1]] : order[s];
    }
    cloud.uniqueIndex.assign(input.size(), -1);
    cloud.points.clear();
    for (std::size_t i = 0; i < input.size(); ++i) {
        int leader = groupLeader[i];
        if (cloud.uniqueIndex[leader] < 0) {
            cloud.uniqueIndex[leader] = static_cast<int>(cloud.points.size());
            cloud.points.push_back(input[leader]);
        }
        cloud.uniqueIndex[i] = cloud.uniqueIndex[leader];
    }
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
    if (lambda(1) <= 1e-12 * lambda(2)) {
        throw InvalidInput(
            "All points lie on one straight line: such a cloud is already a curve and has "
            "no surface to contract.");
    }
}

}  // namespace

Eigen::AlignedBox3d boundingBox(const PointList& points) {
    Eigen::AlignedBox3d box;
    for (const Point& p : points) box.extend(p);
    return box;
}

NormalizedCloud normalizeCloud(const PointList& input, std::size_t minimumUniquePoints,
                               const OutlierParameters& outliers) {
    if (input.empty()) throw InvalidInput("The point layer is empty.");
    rejectNonFinite(input, "points", Remedy::take(Step::RemoveNonFinitePoints));

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

    rejectCollinear(cloud.points);
    return cloud;
}

}  // namespace pcskeleton
