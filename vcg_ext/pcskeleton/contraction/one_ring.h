// Step 1 of the paper (Sec. III-A): each point's 1-ring, computed once on the input.
//
// For point i: its k nearest neighbours are projected onto their PCA tangent plane, and
// the triangles around i in the 2-D Delaunay triangulation of i and its neighbours (its
// "fan") define i's 1-ring. The fan is kept fixed while the points move; only the
// Laplacian weights change. Not in the paper: neighbours on another part's wall facing
// i's own across a gap can be left out first (facing_walls.h).
#pragma once

#include "pcskeleton/contraction/point_cloud_input.h"
#include "pcskeleton/core/progress.h"

#include <array>
#include <cstddef>
#include <vector>

namespace pcskeleton {

// The paper's rule for k: 0.012 n, restricted to [8, 30].
int paperNeighbourCount(std::size_t pointCount);
// The default k: the paper's rule, but at least one neighbour per kPointsPerDefaultNeighbour
// points, up to kFewestDefaultNeighbours (reached at 600 points). The paper's rule gives fewer
// than 20 below 1667 points, a size its experiments did not have (it subsampled to about
// 10K): there a plate's fans from so few neighbours contract it into a web of false loops,
// and tubes lose loops and tips; on the sparsest clouds more neighbours reach across small
// holes instead (docs/benchmarks.md, "Sparse clouds").
inline constexpr int kFewestDefaultNeighbours = 20;
inline constexpr std::size_t kPointsPerDefaultNeighbour = 30;
int defaultNeighbourCount(std::size_t pointCount);

// Whether the 1-rings leave out neighbours on a wall facing the point's own (facing_walls.h).
enum class FacingWalls { Keep, LeaveOut };

class OneRings {
public:
    // Triangle (i, a, b) of i's fan is stored as {a, b}, counter-clockwise around i in the
    // tangent plane. Fans of points on the rim of their neighbourhood are open.
    using FanTriangle = std::array<int, 2>;

    std::size_t size() const { return fanOffsets_.empty() ? 0 : fanOffsets_.size() - 1; }
    int neighbourCount() const { return k_; }

    const FanTriangle* fanBegin(std::size_t i) const { return fanTriangles_.data() + fanOffsets_[i]; }
    const FanTriangle* fanEnd(std::size_t i) const { return fanTriangles_.data() + fanOffsets_[i + 1]; }
    // The 1-ring: distinct vertices of i's fan, ascending.
    const int* ringBegin(std::size_t i) const { return ring_.data() + ringOffsets_[i]; }
    const int* ringEnd(std::size_t i) const { return ring_.data() + ringOffsets_[i + 1]; }
    std::size_t ringSize(std::size_t i) const { return ringOffsets_[i + 1] - ringOffsets_[i]; }
    std::size_t totalRingEntries() const { return ring_.size(); }

    // Of the k nearest neighbours of all points, how many were left out as on a facing wall.
    std::size_t facingNeighboursLeftOut() const { return facingLeftOut_; }

    // Builds the rings of `points` (no exact duplicates allowed) with k neighbours.
    static OneRings compute(const PointList& points, int k, FacingWalls facingWalls = FacingWalls::Keep,
                            const ProgressCallback& progress = {});

private:
    int k_ = 0;
    std::size_t facingLeftOut_ = 0;
    std::vector<std::size_t> fanOffsets_, ringOffsets_;
    std::vector<FanTriangle> fanTriangles_;
    std::vector<int> ring_;
};

// The extent S_i of each point's 1-ring at `positions`: the mean distance to its
// 1-ring neighbours (0 for a point without neighbours). Its shrinking measures contraction.
std::vector<double> ringExtents(const OneRings& rings, const PointList& positions);

}  // namespace pcskeleton
