#include "pcskeleton/reconstruction/vertex_fitting.h"

#include "pcskeleton/internal/local_plane.h"
#include "pcskeleton/internal/spatial_index.h"

#include <algorithm>
#include <cmath>

namespace pcskeleton {

namespace {

// Few neighbours follow a clean surface's curvature closely; over noise, more average it
// (docs/benchmarks.md#measurements-behind-the-constants). The noisy fit is used where the clean
// one's points scatter off it by more than a quarter cell.
constexpr int kCleanNeighbours = 16;
constexpr int kNoisyNeighbours = 40;
constexpr double kNoisyResidual = 0.25;  // cells
constexpr double kDataReach = 1.5;    // cells: no input point nearer, no data here
constexpr double kLargestMove = 1.0;  // cells
// The points' plane and the surface's normal may differ by up to 45 degrees.
constexpr double kLeastNormalAgreement = 0.7071;

// Twice the triangle's area along its normal, its corners taken from `vertices`.
Point triangleNormal(const PointList& vertices, const std::array<int, 3>& t) {
    return (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
}

// Area-weighted normals of the vertices (unnormalised: the sums of their triangles').
PointList vertexNormals(const TriangleMesh& mesh) {
    PointList normals(mesh.vertices.size(), Point::Zero());
    for (const auto& t : mesh.triangles) {
        const Point n = triangleNormal(mesh.vertices, t);
        for (int v : t) normals[std::size_t(v)] += n;
    }
    return normals;
}

}  // namespace

VertexFittingReport fitVerticesToPoints(TriangleMesh& mesh, const PointList& points, double cell) {
    VertexFittingReport report;
    if (points.size() < std::size_t(kNoisyNeighbours) || !(cell > 0)) return report;
    const PointIndex index(points);
    const PointList normals = vertexNormals(mesh);
    std::vector<double> move(mesh.vertices.size(), 0.0);
    std::vector<Point> direction(mesh.vertices.size(), Point::Zero());
#pragma omp parallel
    {
        std::vector<int> found;
#pragma omp for schedule(static)
        for (long i = 0; i < long(mesh.vertices.size()); ++i) {
            const Point& v = mesh.vertices[std::size_t(i)];
            index.nearest(v, kCleanNeighbours, found);
            if (found.empty() || (points[std::size_t(found.front())] - v).norm() > kDataReach * cell) continue;
            LocalQuadric quadric = fitLocalQuadric(points, found);
            if (quadric.residual > kNoisyResidual * cell) {
                index.nearest(v, kNoisyNeighbours, found);
                quadric = fitLocalQuadric(points, found);
            }
            const Point normal = quadric.plane.axes.col(0);
            const Point surfaceNormal = normals[std::size_t(i)].normalized();
            if (!surfaceNormal.allFinite() || std::abs(normal.dot(surfaceNormal)) < kLeastNormalAgreement) continue;
            const Eigen::Vector3d l = quadric.local(v);
            const double offset = quadric.heightAt(l.x(), l.y()) - l.z();
            if (!std::isfinite(offset)) continue;
            // Over noisy points the fit is as uncertain as the level set: trust it less.
            const double trust = 1.0 / (1.0 + std::pow(quadric.residual / cell, 2.0));
            move[std::size_t(i)] = trust * std::clamp(offset, -kLargestMove * cell, kLargestMove * cell);
            direction[std::size_t(i)] = normal;
        }
    }
    // A move that turns a triangle over is undone (with those of the triangle's other
    // vertices), until no triangle is turned: the surface may not fold onto itself.
    const PointList before = mesh.vertices;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) mesh.vertices[i] += move[i] * direction[i];
    for (bool undone = true; undone;) {
        undone = false;
        for (const auto& t : mesh.triangles) {
            if (triangleNormal(before, t).dot(triangleNormal(mesh.vertices, t)) > 0) continue;
            for (int v : t) {
                if (move[std::size_t(v)] == 0.0) continue;
                move[std::size_t(v)] = 0.0;
                mesh.vertices[std::size_t(v)] = before[std::size_t(v)];
                undone = true;
                ++report.undone;
            }
        }
    }
    double total = 0.0;
    for (double m : move) {
        if (m == 0.0) continue;
        total += std::abs(m);
        ++report.moved;
    }
    if (report.moved > 0) report.meanMove = total / double(report.moved) / cell;
    return report;
}

}  // namespace pcskeleton
