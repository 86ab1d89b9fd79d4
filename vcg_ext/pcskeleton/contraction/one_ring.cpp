#include "pcskeleton/contraction/one_ring.h"

#include "pcskeleton/contraction/facing_walls.h"
#include "pcskeleton/internal/spatial_index.h"

#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/property_map.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace pcskeleton {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;

using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay2 = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;
using HullTraits = CGAL::Convex_hull_traits_adapter_2<Kernel, CGAL::Pointer_property_map<Point2>::type>;

struct LocalFan {
    std::vector<OneRings::FanTriangle> triangles;
    std::vector<int> ring;
};

// Everything one thread needs to build fans, reused from point to point.
class FanBuilder {
public:
    // `outward`: the points' outward normals (facing_walls.h), or null to keep every neighbour.
    FanBuilder(const PointList& points, const PointIndex& index, int k, const PointList* outward)
        : points_(points), index_(index), k_(k), outward_(outward) {}

    std::size_t facingLeftOut() const { return facingLeftOut_; }

    void build(int i, LocalFan& fan) {
        fan.triangles.clear();
        fan.ring.clear();
        gatherNeighbours(i);
        projectOnTangentPlane(i);
        triangulate(fan);
        std::sort(fan.ring.begin(), fan.ring.end());
        fan.ring.erase(std::unique(fan.ring.begin(), fan.ring.end()), fan.ring.end());
    }

private:
    void gatherNeighbours(int i) {
        // k + 1 because the query point finds itself.
        index_.nearest(points_[i], k_ + 1, neighbours_);
        neighbours_.erase(std::remove(neighbours_.begin(), neighbours_.end(), i), neighbours_.end());
        if (outward_) leaveOutFacingWalls(i);
    }

    void leaveOutFacingWalls(int i) {
        const PointList& out = *outward_;
        const auto onFacing = [&](int j) { return onFacingWall(points_[i], out[i], points_[j], out[j]); };
        const auto kept = std::remove_if(neighbours_.begin(), neighbours_.end(), onFacing);
        facingLeftOut_ += std::size_t(neighbours_.end() - kept);
        neighbours_.erase(kept, neighbours_.end());
    }

    void projectOnTangentPlane(int i) {
        Point mean = points_[i];
        for (int j : neighbours_) mean += points_[j];
        mean /= static_cast<double>(neighbours_.size() + 1);
        Eigen::Matrix3d covariance = (points_[i] - mean) * (points_[i] - mean).transpose();
        for (int j : neighbours_) covariance += (points_[j] - mean) * (points_[j] - mean).transpose();
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
        eigen.computeDirect(covariance);
        // Eigenvalues ascend: the two largest span the tangent plane.
        const Eigen::Vector3d u = eigen.eigenvectors().col(2);
        const Eigen::Vector3d v = eigen.eigenvectors().col(1);
        projected_.clear();
        for (int j : neighbours_) {
            const Point d = points_[j] - points_[i];
            const Point2 q(d.dot(u), d.dot(v));
            // A neighbour projecting onto the centre's spot carries no tangential information.
            if (q != Point2(0, 0)) projected_.emplace_back(q, j);
        }
    }

    // The centre's Delaunay neighbours, without triangulating the whole neighbourhood. A
    // circle through the centre with no neighbour inside becomes, under inversion about the
    // centre (q -> q / |q|^2, which keeps each direction), a line with every inverted
    // neighbour on the centre's side: the centre's Delaunay neighbours are the vertices of
    // the convex hull of the inverted neighbours and the centre, in the same angular order,
    // and each hull edge between two neighbours is a fan triangle. A hull is a few times
    // cheaper than a Delaunay triangulation of the same points, and the 1-rings are most of
    // a small cloud's time.
    void triangulate(LocalFan& fan) {
        inverted_.clear();
        for (const auto& projected : projected_) {
            const Point2& q = projected.first;
            const double d2 = q.x() * q.x() + q.y() * q.y();
            inverted_.emplace_back(q.x() / d2, q.y() / d2);
        }
        const int centre = int(inverted_.size());
        inverted_.emplace_back(0, 0);
        keys_.resize(inverted_.size());
        std::iota(keys_.begin(), keys_.end(), 0);
        hull_.clear();
        CGAL::convex_hull_2(keys_.begin(), keys_.end(), std::back_inserter(hull_),
                            HullTraits(CGAL::make_property_map(inverted_)));
        if (hull_.size() < 3) {
            // Every neighbour on one line through the centre: no triangle.
            triangulateDegenerate(fan);
            return;
        }
        for (std::size_t h = 0; h < hull_.size(); ++h) {
            const int a = hull_[h], b = hull_[(h + 1) % hull_.size()];
            if (a == centre || b == centre) continue;  // the centre is on the neighbourhood's boundary
            // The centre between a and b on one line (its hull edge passes through the
            // centre): a boundary, not a triangle.
            if (CGAL::orientation(Point2(0, 0), projected_[a].first, projected_[b].first) != CGAL::LEFT_TURN) continue;
            fan.triangles.push_back({projected_[a].second, projected_[b].second});
            fan.ring.push_back(projected_[a].second);
            fan.ring.push_back(projected_[b].second);
        }
    }

    void triangulateDegenerate(LocalFan& fan) {
        triangulation_.clear();
        // Only the neighbours' infos are read: the centre's stays unset.
        const Delaunay2::Vertex_handle centre = triangulation_.insert(Point2(0, 0));
        triangulation_.insert(projected_.begin(), projected_.end());
        // Collinear neighbourhood: no triangle, hence no Laplacian weight, but the two
        // neighbours along the line still measure the extent.
        if (triangulation_.dimension() != 1) return;
        Delaunay2::Vertex_circulator vertex = triangulation_.incident_vertices(centre), end = vertex;
        if (vertex == nullptr) return;
        do {
            if (!triangulation_.is_infinite(vertex)) fan.ring.push_back(vertex->info());
        } while (++vertex != end);
    }

    const PointList& points_;
    const PointIndex& index_;
    int k_;
    const PointList* outward_;
    std::size_t facingLeftOut_ = 0;
    std::vector<int> neighbours_;
    std::vector<std::pair<Point2, int>> projected_;
    std::vector<Point2> inverted_;
    std::vector<int> keys_, hull_;
    Delaunay2 triangulation_;
};

}  // namespace

int paperNeighbourCount(std::size_t pointCount) {
    const long k = std::lround(0.012 * static_cast<double>(pointCount));
    return static_cast<int>(std::clamp<long>(k, 8, 30));
}

int defaultNeighbourCount(std::size_t pointCount) {
    const long fewest = std::clamp<long>(long(pointCount / kPointsPerDefaultNeighbour), 8, kFewestDefaultNeighbours);
    return std::max(paperNeighbourCount(pointCount), static_cast<int>(fewest));
}

OneRings OneRings::compute(const PointList& points, int k, FacingWalls facingWalls, const ProgressCallback& progress) {
    const std::size_t n = points.size();
    OneRings rings;
    rings.k_ = std::min<int>(k, static_cast<int>(n) - 1);

    const PointIndex index(points);
    report(progress, 10, "Neighbourhoods: k-d tree built");
    const PointList outward = facingWalls == FacingWalls::LeaveOut ? outwardNormals(points, index) : PointList();

    // Each thread handles a contiguous block of points, so concatenating the threads'
    // outputs in order gives the fans in point order.
    std::vector<std::vector<OneRings::FanTriangle>> blockTriangles;
    std::vector<std::vector<int>> blockRings;
    std::vector<std::size_t> fanCount(n), ringCount(n);
#pragma omp parallel
    {
        int threads = 1, thread = 0;
#ifdef _OPENMP
        threads = omp_get_num_threads();
        thread = omp_get_thread_num();
#endif
#pragma omp single
        {
            blockTriangles.resize(threads);
            blockRings.resize(threads);
        }
        const std::size_t begin = n * thread / threads, end = n * (thread + 1) / threads;
        FanBuilder builder(points, index, rings.k_, outward.empty() ? nullptr : &outward);
        LocalFan fan;
        for (std::size_t i = begin; i < end; ++i) {
            builder.build(static_cast<int>(i), fan);
            fanCount[i] = fan.triangles.size();
            ringCount[i] = fan.ring.size();
            blockTriangles[thread].insert(blockTriangles[thread].end(), fan.triangles.begin(), fan.triangles.end());
            blockRings[thread].insert(blockRings[thread].end(), fan.ring.begin(), fan.ring.end());
            if (thread == 0 && (i - begin) % 4096 == 0) {
                report(progress, 10 + static_cast<int>(90 * (i - begin) / std::max<std::size_t>(1, end - begin)),
                       "Neighbourhoods: tangent-plane Delaunay 1-rings");
            }
        }
#pragma omp atomic
        rings.facingLeftOut_ += builder.facingLeftOut();
    }

    rings.fanOffsets_.assign(n + 1, 0);
    rings.ringOffsets_.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        rings.fanOffsets_[i + 1] = rings.fanOffsets_[i] + fanCount[i];
        rings.ringOffsets_[i + 1] = rings.ringOffsets_[i] + ringCount[i];
    }
    rings.fanTriangles_.reserve(rings.fanOffsets_[n]);
    rings.ring_.reserve(rings.ringOffsets_[n]);
    for (std::size_t t = 0; t < blockTriangles.size(); ++t) {
        rings.fanTriangles_.insert(rings.fanTriangles_.end(), blockTriangles[t].begin(), blockTriangles[t].end());
        rings.ring_.insert(rings.ring_.end(), blockRings[t].begin(), blockRings[t].end());
        std::vector<OneRings::FanTriangle>().swap(blockTriangles[t]);
        std::vector<int>().swap(blockRings[t]);
    }
    report(progress, 100, "Neighbourhoods: done");
    return rings;
}

std::vector<double> ringExtents(const OneRings& rings, const PointList& positions) {
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(rings.size());
    std::vector<double> extents(n, 0.0);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        std::size_t count = rings.ringSize(i);
        if (count == 0) continue;
        double sum = 0;
        for (const int* j = rings.ringBegin(i); j != rings.ringEnd(i); ++j) sum += (positions[*j] - positions[i]).norm();
        extents[i] = sum / static_cast<double>(count);
    }
    return extents;
}

}  // namespace pcskeleton
