#include "pcskeleton/contraction/point_denoising.h"

#include "pcskeleton/core/errors.h"
#include "pcskeleton/internal/local_plane.h"
#include "pcskeleton/internal/spatial_index.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <string>

namespace pcskeleton {

double surfaceNoise(const PointList& points, int neighbours) {
    const PointIndex index(points);
    const long samples = long((points.size() + 6) / 7);
    std::vector<double> ratios(std::size_t(samples), -1.0);
#pragma omp parallel
    {
        std::vector<int> found;
#pragma omp for schedule(static)
        for (long s = 0; s < samples; ++s) {
            index.nearest(points[std::size_t(s) * 7], neighbours, found);
            const LocalPlane frame = fitLocalPlane(points, found);
            const Point& centroid = frame.centroid;
            const Point normal = frame.axes.col(0), u = frame.axes.col(2), v = frame.axes.col(1);
            Eigen::MatrixXd basis(found.size(), 6);
            Eigen::VectorXd height(found.size());
            double extent = 0;
            for (std::size_t r = 0; r < found.size(); ++r) {
                const Point d = points[std::size_t(found[r])] - centroid;
                const double x = d.dot(u), y = d.dot(v);
                basis.row(Eigen::Index(r)) << 1, x, y, x * x, x * y, y * y;
                height[Eigen::Index(r)] = d.dot(normal);
                extent += x * x + y * y;
            }
            extent = std::sqrt(extent / double(found.size()));
            const Eigen::VectorXd fit = basis.colPivHouseholderQr().solve(height);
            const double residual = std::sqrt((basis * fit - height).squaredNorm() / double(found.size()));
            if (extent > 0) ratios[std::size_t(s)] = residual / extent;
        }
    }
    ratios.erase(std::remove(ratios.begin(), ratios.end(), -1.0), ratios.end());
    if (ratios.empty()) return 0.0;
    std::nth_element(ratios.begin(), ratios.begin() + long(ratios.size() / 2), ratios.end());
    return ratios[ratios.size() / 2];
}

DenoisingChoice chooseDenoising(const PointList& points, int neighbours, int requested) {
    if (requested == kAutomaticDenoising) {
        const double noise = surfaceNoise(points, neighbours);
        return {noise > kNoisySurface ? kPassesForNoisySurface : 0, noise};
    }
    if (requested < 0 || requested > kMaximumDenoisingPasses) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::DenoisingPasses, "must be between 0 (off) and " + std::to_string(kMaximumDenoisingPasses) +
                                            ", or -1 (automatic: only noisy clouds)."));
    }
    return {requested, -1.0};
}

PointList denoisedCopy(const PointList& points, int neighbours, int passes) {
    PointList current = points;
    for (int pass = 0; pass < passes; ++pass) {
        const PointIndex index(current);
        PointList next(current.size());
#pragma omp parallel
        {
            std::vector<int> found;
#pragma omp for schedule(static)
            for (long i = 0; i < long(current.size()); ++i) {
                index.nearest(current[std::size_t(i)], neighbours, found);
                const LocalPlane frame = fitLocalPlane(current, found);
                const Point normal = frame.axes.col(0);
                const Point& p = current[std::size_t(i)];
                next[std::size_t(i)] = p - normal * normal.dot(p - frame.centroid);
            }
        }
        current.swap(next);
    }
    return current;
}

}  // namespace pcskeleton
