#include "pcskeleton/reconstruction/point_weights.h"

#include "pcskeleton/internal/local_plane.h"
#include "pcskeleton/internal/spatial_index.h"

#include <algorithm>
#include <cmath>

namespace pcskeleton {

namespace {

// Neighbours of the spread: enough for a plane fit to average the noise, few enough to stay
// on one side of a thin part.
constexpr int kSpreadNeighbours = 16;
// How fast a point's weight falls once its spread passes a cell: the fourth power keeps
// points scattered by half a cell at 94% and cuts those scattered by two cells to 6%.
// Chosen with bench_surface (docs/benchmarks.md#measurements-behind-the-constants).
constexpr double kFalloffPower = 4.0;

}  // namespace

SurfacePointWeights noiseAdaptedWeights(const PointList& points, double cell, double surfaceWeight) {
    SurfacePointWeights result;
    result.weight.assign(points.size(), surfaceWeight);
    if (points.size() <= std::size_t(kSpreadNeighbours)) return result;
    const PointIndex index(points);
#pragma omp parallel
    {
        std::vector<int> neighbours;
#pragma omp for schedule(static)
        for (long i = 0; i < long(points.size()); ++i) {
            index.nearest(points[std::size_t(i)], kSpreadNeighbours, neighbours);
            // Root-mean-square distance from the plane: the smallest principal spread.
            const double spread = std::sqrt(std::max(0.0, fitLocalPlane(points, neighbours).variances[0])) / cell;
            result.weight[std::size_t(i)] = surfaceWeight / (1.0 + std::pow(spread, kFalloffPower));
        }
    }
    double sum = 0;
    for (double w : result.weight) sum += w;
    result.meanShare = sum / double(points.size()) / surfaceWeight;
    return result;
}

}  // namespace pcskeleton
