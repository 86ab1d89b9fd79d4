// The fine pass of the reconstruction (not the paper's): where data exists, each vertex
// of the extracted surface moves along the local surface normal onto a quadratic height
// field fitted to its nearest input points (16; 40 where those scatter off their fit by a
// quarter cell or more: noise). The field's smoothness term rounds thin walls inward
// against the data term, by about a tenth of a cell at any resolution; a local fit of the
// points has no such bias. Vertices move, triangles do not change: the surface keeps the
// topology the skeleton gave it. A move is at most a cell, scaled down where the points
// scatter off their fit by a cell or more (the fit is then no surer than the level set),
// undone where it would turn a triangle over, and not made where the points' plane
// disagrees with the surface's normal by more than 45 degrees (the other wall of a part
// thinner than the neighbourhood) or where no point is within 1.5 cells (no data there).
// Its effect on the distance to the true surface: docs/benchmarks.md#measurements-behind-the-constants.
#pragma once

#include "pcskeleton/reconstruction/iso_surface.h"

namespace pcskeleton {

struct VertexFittingReport {
    std::size_t moved = 0;      // vertices moved onto the points' local surface
    double meanMove = 0.0;      // their mean move, in cells
    std::size_t undone = 0;     // moves undone because they turned a triangle over
};

// `mesh` and `points` in the same frame, `cell` the grid's spacing there.
VertexFittingReport fitVerticesToPoints(TriangleMesh& mesh, const PointList& points, double cell);

}  // namespace pcskeleton
