#include "support/sampled_shapes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
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

double distanceToCurve(const Point& p, const Polyline& curve) {
    double best = std::numeric_limits<double>::infinity();
    for (const Segment& s : curve) best = std::min(best, distanceToSegment(p, s.a, s.b));
    return best;
}

Polyline circle(const Point& centre, double radius, int sides) {
    Polyline curve;
    auto corner = [&](int i) {
        const double angle = 2 * kPi * i / sides;
        return Point(centre.x() + radius * std::cos(angle), centre.y() + radius * std::sin(angle), centre.z());
    };
    for (int i = 0; i < sides; ++i) curve.push_back({corner(i), corner((i + 1) % sides)});  // exactly closed
    return curve;
}

SkeletonGraph curveSkeleton(const Polyline& curve, double radius) {
    SkeletonGraph skeleton;
    auto nodeAt = [&](const Point& p) {
        for (std::size_t n = 0; n < skeleton.nodes.size(); ++n)
            if ((skeleton.nodes[n] - p).norm() < 1e-12) return int(n);
        skeleton.nodes.push_back(p);
        skeleton.radii.push_back(radius);
        return int(skeleton.nodes.size() - 1);
    };
    for (const Segment& s : curve) skeleton.edges.push_back({nodeAt(s.a), nodeAt(s.b)});
    normalizeEdges(skeleton.edges);
    return skeleton;
}

PointList withoutSector(const PointList& points, const Point& centre, double fromAngle, double sweep) {
    PointList kept;
    for (const Point& p : points) {
        double offset = std::atan2(p.y() - centre.y(), p.x() - centre.x()) - fromAngle;
        offset -= 2 * kPi * std::floor(offset / (2 * kPi));
        if (offset >= sweep) kept.push_back(p);
    }
    return kept;
}

PointList tube(const Polyline& centreCurve, double radius, std::size_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    // Each capsule's area: side 2 pi r L plus two half spheres.
    std::vector<double> cumulativeArea;
    double total = 0.0;
    for (const Segment& s : centreCurve) {
        total += 2 * kPi * radius * (s.b - s.a).norm() + 4 * kPi * radius * radius;
        cumulativeArea.push_back(total);
    }
    PointList points;
    points.reserve(n);
    while (points.size() < n) {
        const double pick = unit(rng) * total;
        const std::size_t k = std::lower_bound(cumulativeArea.begin(), cumulativeArea.end(), pick) - cumulativeArea.begin();
        const Segment& s = centreCurve[std::min(k, centreCurve.size() - 1)];
        const Point axis = s.b - s.a;
        const double length = axis.norm();
        const Point direction = axis / length;
        Point p;
        if (unit(rng) * (length + 2 * radius) < length) {
            // A unit vector orthogonal to the axis, uniform in angle.
            Point normal = direction.unitOrthogonal();
            const double angle = 2 * kPi * unit(rng);
            normal = std::cos(angle) * normal + std::sin(angle) * direction.cross(normal);
            p = s.a + unit(rng) * axis + radius * normal;
        } else {
            const Point d = uniformOnUnitSphere(rng);
            p = (d.dot(direction) > 0 ? s.b : s.a) + radius * d;
        }
        if (distanceToCurve(p, centreCurve) >= radius * (1 - 1e-9)) points.push_back(p);
    }
    return points;
}

double meanDistanceToCylinderWall(const PointList& points, double radius, double fromZ, double toZ) {
    double sum = 0;
    int count = 0;
    for (const Point& v : points) {
        if (v.z() < fromZ || v.z() > toZ) continue;
        sum += std::abs(std::hypot(v.x(), v.y()) - radius);
        ++count;
    }
    return count ? sum / count : 1e9;
}

}  // namespace pcskeleton::shapes

namespace pcskeleton::shapes {

Triangles sheet(const std::function<Point(double u, double v)>& map, int cellsU, int cellsV,
                const std::function<bool(double u, double v)>& keep) {
    Triangles triangles;
    for (int i = 0; i < cellsU; ++i) {
        for (int j = 0; j < cellsV; ++j) {
            const double u0 = double(i) / cellsU, u1 = double(i + 1) / cellsU;
            const double v0 = double(j) / cellsV, v1 = double(j + 1) / cellsV;
            if (keep && !keep(0.5 * (u0 + u1), 0.5 * (v0 + v1))) continue;
            const Point a = map(u0, v0), b = map(u1, v0), c = map(u1, v1), d = map(u0, v1);
            triangles.push_back({a, b, c});
            triangles.push_back({a, c, d});
        }
    }
    return triangles;
}

double area(const Triangles& triangles) {
    double total = 0.0;
    for (const Triangle& t : triangles) total += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
    return total;
}

PointList sample(const Triangles& triangles, std::size_t n, std::uint32_t seed) {
    std::vector<double> cumulative;
    double total = 0.0;
    for (const Triangle& t : triangles) cumulative.push_back(total += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm());
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PointList points;
    points.reserve(n);
    for (std::size_t i = 0; i < n && !triangles.empty(); ++i) {
        const std::size_t k =
            std::lower_bound(cumulative.begin(), cumulative.end(), unit(rng) * total) - cumulative.begin();
        const Triangle& t = triangles[std::min(k, triangles.size() - 1)];
        const double a = std::sqrt(unit(rng)), b = unit(rng);
        points.push_back((1 - a) * t[0] + a * (1 - b) * t[1] + a * b * t[2]);
    }
    return points;
}

}  // namespace pcskeleton::shapes
