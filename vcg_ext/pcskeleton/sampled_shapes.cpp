#include "pcskeleton/sampled_shapes.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace pcskeleton::shapes {

namespace {

constexpr double kPi = 3.14159265358979323846;

Point uniformOnUnitSphere(std::mt19937& rng) {
    std::normal_distribution<double> gauss;
    Point d;
    do {
        d = Point(gauss(rng), gauss(rng), gauss(rng));
    } while (d.norm() < 1e-9);
    return d.normalized();
}

}  // namespace

PointList cylinder(std::size_t n, double radius, double length, bool capped, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double sideArea = 2 * kPi * radius * length;
    const double capArea = capped ? 4 * kPi * radius * radius : 0.0;
    PointList points;
    points.reserve(n);
    while (points.size() < n) {
        if (unit(rng) * (sideArea + capArea) < sideArea) {
            const double angle = 2 * kPi * unit(rng);
            points.emplace_back(radius * std::cos(angle), radius * std::sin(angle), length * unit(rng));
        } else {
            Point d = uniformOnUnitSphere(rng) * radius;
            if (d.z() > 0) d.z() += length;
            points.push_back(d);
        }
    }
    return points;
}

PointList torus(std::size_t n, double majorRadius, double minorRadius, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PointList points;
    points.reserve(n);
    // Rejection on the area element (R + r cos v) makes the sampling uniform by area.
    while (points.size() < n) {
        const double u = 2 * kPi * unit(rng), v = 2 * kPi * unit(rng);
        const double ring = majorRadius + minorRadius * std::cos(v);
        if (unit(rng) * (majorRadius + minorRadius) > ring) continue;
        points.emplace_back(ring * std::cos(u), ring * std::sin(u), minorRadius * std::sin(v));
    }
    return points;
}

PointList sphere(std::size_t n, double radius, std::uint32_t seed) {
    std::mt19937 rng(seed);
    PointList points;
    points.reserve(n);
    while (points.size() < n) points.push_back(uniformOnUnitSphere(rng) * radius);
    return points;
}

double distanceToSegment(const Point& p, const Point& a, const Point& b) {
    const Point ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * ab)).norm();
}

}  // namespace pcskeleton::shapes
