#include "pcskeleton/contraction/medial_pull.h"

#include "pcskeleton/internal/local_plane.h"
#include "pcskeleton/internal/spatial_index.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <tuple>

namespace pcskeleton {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using OrientedPoint = std::tuple<Kernel::Point_3, Kernel::Vector_3, std::size_t>;

// A point's surface normal is read from its twelve nearest, as the facing walls' is from
// ten: few enough to stay on its own wall, enough to average the noise left after denoising.
constexpr int kNormalNeighbours = 12;
// A ball that is still empty at half the cloud's diagonal opens onto the outside: a scan's
// unseen side, or a sheet seen from one side. Such a point has no medial centre.
constexpr double kLargestBallShare = 0.5;
// The shrinking ball's radius falls with every step and settles within a few; this bounds
// the steps on degenerate neighbourhoods.
constexpr int kMaxShrinkSteps = 50;
// The points nearest a ball's centre that are tested for being inside it: enough that one
// beyond p's own surface is among them once the ball reaches across the shape.
constexpr int kBallProbes = 6;

// Each point's surface: the normal of the plane through its nearest and how far they reach.
struct LocalSurfaces {
    PointList normals;
    std::vector<double> reach;
};

LocalSurfaces localSurfaces(const PointList& points, const PointIndex& index) {
    const std::ptrdiff_t n = std::ptrdiff_t(points.size());
    LocalSurfaces surfaces{PointList(points.size(), Point::Zero()), std::vector<double>(points.size(), 0.0)};
#pragma omp parallel
    {
        std::vector<int> nearest;
#pragma omp for schedule(static)
        for (std::ptrdiff_t i = 0; i < n; ++i) {
            const Point& p = points[std::size_t(i)];
            index.nearest(p, kNormalNeighbours + 1, nearest);
            if (nearest.size() < 3) continue;
            surfaces.normals[std::size_t(i)] = fitLocalPlane(points, nearest).axes.col(0);
            surfaces.reach[std::size_t(i)] = (points[std::size_t(nearest.back())] - p).norm();
        }
    }
    return surfaces;
}

// Flips the normals so that neighbours agree, by CGAL's propagation along a minimum
// spanning tree from the highest point, whose normal points up (out of the shape). Points
// the propagation does not reach keep a zero normal.
void orientNormals(const PointList& points, PointList& normals) {
    std::vector<OrientedPoint> oriented;
    oriented.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Point& p = points[i];
        const Point& v = normals[i];
        oriented.emplace_back(Kernel::Point_3(p.x(), p.y(), p.z()), Kernel::Vector_3(v.x(), v.y(), v.z()), i);
    }
    const auto unoriented = CGAL::mst_orient_normals(
        oriented, kNormalNeighbours,
        CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, OrientedPoint>())
            .normal_map(CGAL::Nth_of_tuple_property_map<1, OrientedPoint>()));
    for (auto it = oriented.begin(); it != oriented.end(); ++it) {
        const std::size_t i = std::get<2>(*it);
        const Kernel::Vector_3& v = std::get<1>(*it);
        normals[i] = it < unoriented ? Point(v.x(), v.y(), v.z()) : Point::Zero();
    }
}

// The centre of the largest empty ball touching p whose centre lies along `inward`, by
// shrinking: a ball that holds a point q is replaced by the one through p and q, until none
// is inside. Points within `reach` of p are not tested: they lie on p's own surface, and
// an error of a few degrees in the normal puts them inside any large ball. False when the
// ball of radius `largest` is already empty.
bool shrinkBall(const PointList& points, const PointIndex& index, const Point& p, double reach, const Point& inward,
                double largest, std::vector<int>& nearest, Point& centre) {
    double radius = largest;
    for (int step = 0; step < kMaxShrinkSteps; ++step) {
        const Point c = p + radius * inward;
        index.nearest(c, kBallProbes, nearest);
        const auto far = std::find_if(nearest.begin(), nearest.end(),
                                      [&](int j) { return (points[std::size_t(j)] - p).norm() > reach; });
        if (far == nearest.end()) break;  // only p's own surface at the ball's edge
        const Point& q = points[std::size_t(*far)];
        if ((q - c).norm() >= radius) break;  // empty: p's ball
        // Inside the ball, so d·inward > |d|²/(2 radius) > 0, and the new radius is smaller.
        const Point d = q - p;
        radius = d.squaredNorm() / (2.0 * d.dot(inward));
    }
    if (radius >= largest) return false;
    centre = p + radius * inward;
    return true;
}

}  // namespace

MedialTargets estimateMedialTargets(const PointList& points) {
    MedialTargets targets;
    targets.centres = points;
    targets.found.assign(points.size(), 0);
    if (points.size() <= std::size_t(kNormalNeighbours)) return targets;

    const PointIndex index(points);
    LocalSurfaces surfaces = localSurfaces(points, index);
    orientNormals(points, surfaces.normals);

    const double largest = kLargestBallShare * boundingBox(points).diagonal().norm();

    const std::ptrdiff_t n = std::ptrdiff_t(points.size());
    std::size_t count = 0;
#pragma omp parallel reduction(+ : count)
    {
        std::vector<int> nearest;
#pragma omp for schedule(dynamic, 256)
        for (std::ptrdiff_t i = 0; i < n; ++i) {
            const std::size_t u = std::size_t(i);
            if (surfaces.normals[u].isZero()) continue;
            Point centre;
            if (!shrinkBall(points, index, points[u], surfaces.reach[u], -surfaces.normals[u], largest, nearest,
                            centre)) {
                continue;
            }
            targets.centres[u] = centre;
            targets.found[u] = 1;
            ++count;
        }
    }
    targets.count = count;
    return targets;
}

}  // namespace pcskeleton
