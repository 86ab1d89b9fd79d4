#include "pcskeleton/reconstruction/point_weights.h"

#include "pcskeleton/internal/spatial_index.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace pcskeleton {

namespace {

// Neighbours of the spread: enough for a plane fit to average the noise, few enough to stay
// on one side of a thin part.
constexpr int kSpreadNeighbours = 16;
// How fast a point's weight falls once its spread passes a cell: the fourth power keeps
// points scattered by half a cell at 94% and cuts those scattered by two cells to 6%.
// By bench_surface (README, Benchmarks): see ReconstructionParameters::adaptToNoise.
constexpr double kFalloffPower = 4.0;

double spreadAcrossPlane(const PointList& points, const std::vector<int>& neighbours) {
    Point mean = Point::Zero();
    for (int j : neighbours) mean += points[std::size_t(j)];
    mean /= double(neighbours.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (int j : neighbours) {
        const Point d = points[std::size_t(j)] - mean;
        covariance += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(covariance / double(neighbours.size()), Eigen::EigenvaluesOnly);
    return std::sqrt(std::max(0.0, eigen.eigenvalues()[0]));  // the smallest: across the plane
}

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
            const double spread = spreadAcrossPlane(points, neighbours) / cell;
            result.weight[std::size_t(i)] = surfaceWeight / (1.0 + std::pow(spread, kFalloffPower));
        }
    }
    double sum = 0;
    for (double w : result.weight) sum += w;
    result.meanShare = sum / double(points.size()) / surfaceWeight;
    return result;
}

}  // namespace pcskeleton
