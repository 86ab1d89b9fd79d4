// Noise-adaptive weights of the surface term (not the paper's, which weighs every point
// alike). A point whose neighbours scatter across the surface by more than a grid cell
// says less about where the surface is: its constraint u(p) = 0 counts less, and the
// smoothness and skeleton terms, which average over many points, count more. On clean
// parts nothing changes: the neighbours lie within a small fraction of a cell of their plane.
//
//     w(p) = w2 / (1 + (s(p) / h)^4)
//
// s(p): the root-mean-square distance of p's nearest neighbours from their least-squares
// plane; h: the grid cell. Both are lengths of the same frame, so the rule has no units.
#pragma once

#include "pcskeleton/core/point.h"

#include <vector>

namespace pcskeleton {

struct SurfacePointWeights {
    std::vector<double> weight;  // per point
    double meanShare = 1.0;      // their mean, as a share of the surface weight w2
};

// `points` and `cell` in the same frame; `surfaceWeight` is w2.
SurfacePointWeights noiseAdaptedWeights(const PointList& points, double cell, double surfaceWeight);

}  // namespace pcskeleton
