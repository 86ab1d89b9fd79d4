#include "pcskeleton/contraction/facing_walls.h"

#include "pcskeleton/internal/local_plane.h"
#include "pcskeleton/internal/spatial_index.h"

#include <cmath>
#include <cstddef>
#include <vector>

namespace pcskeleton {

namespace {

// The surface around a point is read from its ten nearest, as the sheets' flatness is: few
// enough to stay on its own wall where another part is within the 1-ring's reach.
constexpr int kSurfaceNeighbours = 10;
// The curvature says which side is out when its rise across the neighbourhood (the mean
// curvature times the squared extent) is at least this many times the fit's residual.
// Chosen on the tuning half of the robustness suite (docs/benchmarks.md, "Facing walls").
constexpr double kCurvatureOverResidual = 5.0;
// q lies outside p's surface when its offset along p's outward normal is more than half its
// distance (30 degrees or more off the tangent plane).
constexpr double kOutsideShare = 0.5;
// The normals face each other when they are within 60 degrees of opposite.
constexpr double kFacingCosine = -0.5;

}  // namespace

PointList outwardNormals(const PointList& points, const PointIndex& index) {
    const std::ptrdiff_t n = std::ptrdiff_t(points.size());
    PointList normals(points.size(), Point::Zero());
#pragma omp parallel
    {
        std::vector<int> nearest;
#pragma omp for schedule(static)
        for (std::ptrdiff_t i = 0; i < n; ++i) {
            index.nearest(points[std::size_t(i)], kSurfaceNeighbours + 1, nearest);
            if (nearest.size() < std::size_t(kSurfaceNeighbours) + 1) continue;
            const LocalQuadric surface = fitLocalQuadric(points, nearest);
            // h = c3 x² + c4 xy + c5 y² + ...: the surface rises along the plane's normal
            // where c3 + c5 > 0, so outside is the other way.
            const double meanCurvature = surface.coefficients[3] + surface.coefficients[5];
            const double rise = std::abs(meanCurvature) * surface.extent * surface.extent;
            if (!(rise > kCurvatureOverResidual * surface.residual)) continue;
            const Point normal = surface.plane.axes.col(0);
            normals[std::size_t(i)] = meanCurvature > 0 ? Point(-normal) : normal;
        }
    }
    return normals;
}

bool onFacingWall(const Point& p, const Point& pOut, const Point& q, const Point& qOut) {
    const Point d = q - p;
    const double threshold = kOutsideShare * d.norm();
    return d.dot(pOut) > threshold && -d.dot(qOut) > threshold && pOut.dot(qOut) < kFacingCosine;
}

}  // namespace pcskeleton
