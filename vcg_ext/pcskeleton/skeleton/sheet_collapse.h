// Plates and other flat sheets, moved onto their medial axis before thinning.
//
// The cotangent Laplacian of a flat patch is zero, so contraction only erodes a one-sided
// plate at its rim and leaves its middle a flat cloud, which thinning makes a hub node with
// long bones to everything around it. Where contraction left a wide flat patch of the input
// as flat and as wide as it was, its points are moved, within their plane, onto the patch's
// medial axis: a loop around each hole of a plate, one point for a disc. Thinning then makes
// a curve of them as of a contracted tube. Not in the paper (docs/benchmarks.md).
//
// 1. A point lies on a sheet when its neighbours within kNeighbourhoodRadii thinning radii
//    (on a sparse cloud, where they are fewer than kFewestNeighbours, its nearest that many)
//    spread in two directions and hardly in the third (their principal variances).
// 2. Sheet points joined by 1-rings whose planes face the same way form one patch, seeded at
//    the flattest point first. A patch is collapsed when it ends at its rim (a cupped leaf's
//    flat middle goes on into sheet points facing another way), when it is wide
//    (kWidePatchRadii both ways), when contraction left it as wide and flat as it was (a
//    tube's strip narrows), and when it is one layer (a face of a thick closed plate has the
//    other face across it, and contraction handles those).
// 3. The patch takes in the points next to it that lie in its plane, as far off as its own
//    points' noise reaches (the band along a crease where two plates meet goes to the plate
//    whose plane is nearer), is drawn on a grid of half a thinning radius in its plane,
//    closed over gaps into which a disc of 1.5 thinning radii does not fit (the bands a
//    grazing scan leaves between its lines among them), and thinned to its medial axis (the
//    holes that remain kept); spurs shorter than two thinning radii are cut off.
// 4. Each of its points moves to the axis cell nearest it across the patch, keeping its
//    place within its cell and its height above the plane.
#pragma once

#include "pcskeleton/contraction/one_ring.h"
#include "pcskeleton/core/point.h"

#include <cstddef>

namespace pcskeleton {

struct SheetCollapseReport {
    int patches = 0;           // flat patches moved onto their medial axes
    std::size_t points = 0;    // points moved
};

// `original`: the points' positions where contraction started them (their own, or the
// denoised copy of a noisy cloud); `contracted`: where contraction left them (the same
// frame and order; the patches' points are moved in place); `rings`: their 1-rings; `radius`:
// the thinning's ball radius, in that frame.
SheetCollapseReport collapseSheets(const PointList& original, PointList& contracted, const OneRings& rings,
                                   double radius);

}  // namespace pcskeleton
