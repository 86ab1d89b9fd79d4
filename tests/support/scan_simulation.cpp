#include "support/scan_simulation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <unordered_map>

namespace pcskeleton::shapes {

namespace {

// The i-th of `views` directions around the z axis, looking 30 degrees down.
Point viewDirection(int i, int views) {
    const double angle = 2.0 * M_PI * (i + 0.25) / views;
    const double down = M_PI / 6.0;
    return Point(std::cos(angle) * std::cos(down), std::sin(angle) * std::cos(down), -std::sin(down));
}

std::vector<int> visibleIndices(const PointList& dense, const Point& direction, double pixel) {
    const Point view = direction.normalized();
    const Point across = view.unitOrthogonal();
    const Point up = view.cross(across);
    auto pixelOf = [&](const Point& p) {
        const auto column = static_cast<long long>(std::floor(p.dot(across) / pixel));
        const auto row = static_cast<long long>(std::floor(p.dot(up) / pixel));
        // Shifted as unsigned: shifting a negative value left is undefined behaviour.
        return static_cast<long long>((static_cast<unsigned long long>(column) << 32) ^
                                      (static_cast<unsigned long long>(row) & 0xffffffffULL));
    };
    std::unordered_map<long long, double> nearest;
    for (const Point& p : dense) {
        const auto [entry, added] = nearest.emplace(pixelOf(p), p.dot(view));
        if (!added) entry->second = std::min(entry->second, p.dot(view));
    }
    std::vector<int> visible;
    for (std::size_t i = 0; i < dense.size(); ++i) {
        if (dense[i].dot(view) <= nearest[pixelOf(dense[i])] + 2.0 * pixel) visible.push_back(int(i));
    }
    return visible;
}

}  // namespace

PointList withNoise(const PointList& points, double share, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> gaussian(0.0, share * boundingBox(points).diagonal().norm());
    PointList noisy;
    noisy.reserve(points.size());
    for (const Point& p : points) noisy.push_back(p + Point(gaussian(random), gaussian(random), gaussian(random)));
    return noisy;
}

PointList withOutliers(const PointList& points, double share, std::uint32_t seed) {
    const Eigen::AlignedBox3d box = boundingBox(points);
    const Point margin = 0.1 * box.sizes();
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PointList result = points;
    const auto count = static_cast<std::size_t>(std::round(share * points.size()));
    for (std::size_t i = 0; i < count; ++i) {
        const Point t(unit(random), unit(random), unit(random));
        result.push_back(box.min() - margin + t.cwiseProduct(box.sizes() + 2.0 * margin));
    }
    return result;
}

PointList unevenlyDense(const PointList& dense, std::size_t n, double areaShare, std::uint32_t seed) {
    std::mt19937 random(seed);
    const Point anchor = dense[std::uniform_int_distribution<std::size_t>(0, dense.size() - 1)(random)];
    std::vector<int> order(dense.size());
    std::iota(order.begin(), order.end(), 0);
    const std::size_t regionSize = static_cast<std::size_t>(areaShare * dense.size());
    std::nth_element(order.begin(), order.begin() + regionSize, order.end(), [&](int a, int b) {
        return (dense[a] - anchor).squaredNorm() < (dense[b] - anchor).squaredNorm();
    });
    std::shuffle(order.begin(), order.begin() + regionSize, random);
    std::shuffle(order.begin() + regionSize, order.end(), random);
    PointList result;
    const std::size_t inRegion = std::min(n / 2, regionSize);
    for (std::size_t i = 0; i < inRegion; ++i) result.push_back(dense[order[i]]);
    for (std::size_t i = regionSize; i < dense.size() && result.size() < n; ++i) result.push_back(dense[order[i]]);
    return result;
}

PointList visibleFrom(const PointList& dense, const Point& direction, double pixel) {
    PointList visible;
    for (int i : visibleIndices(dense, direction, pixel)) visible.push_back(dense[i]);
    return visible;
}

PointList virtualScans(const PointList& dense, int views, double pixel) {
    std::vector<char> seen(dense.size(), 0);
    for (int v = 0; v < views; ++v) {
        for (int i : visibleIndices(dense, viewDirection(v, views), pixel)) seen[i] = 1;
    }
    PointList result;
    for (std::size_t i = 0; i < dense.size(); ++i) {
        if (seen[i]) result.push_back(dense[i]);
    }
    return result;
}

PointList misalignedScans(const PointList& dense, int views, double pixel, double share, std::uint32_t seed) {
    const Eigen::AlignedBox3d box = boundingBox(dense);
    const double diagonal = box.diagonal().norm();
    const Point centre = box.center();
    std::mt19937 random(seed);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    auto randomUnitVector = [&] { return Point(gaussian(random), gaussian(random), gaussian(random)).normalized(); };
    PointList result;
    for (int v = 0; v < views; ++v) {
        // A rotation by angle a moves points at half the diagonal from the centre by a x diagonal / 2.
        const Eigen::AngleAxisd rotation(2.0 * share, randomUnitVector());
        const Point translation = share * diagonal * randomUnitVector();
        for (const Point& p : visibleFrom(dense, viewDirection(v, views), pixel)) {
            result.push_back(centre + rotation * (p - centre) + translation);
        }
    }
    return result;
}

}  // namespace pcskeleton::shapes
