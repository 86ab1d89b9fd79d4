#include "pcskeleton/contraction/point_denoising.h"

#include "pcskeleton/core/errors.h"
#include "pcskeleton/internal/local_plane.h"
#include "pcskeleton/internal/median.h"
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
            const LocalQuadric quadric = fitLocalQuadric(points, found);
            if (quadric.extent > 0) ratios[std::size_t(s)] = quadric.residual / quadric.extent;
        }
    }
    ratios.erase(std::remove(ratios.begin(), ratios.end(), -1.0), ratios.end());
    if (ratios.empty()) return 0.0;
    return median(std::move(ratios));
}

DenoisingChoice chooseDenoising(const PointList& points, int neighbours, int requested) {
    if (requested == kAutomaticDenoising) {
        const double noise = surfaceNoise(points, neighbours);
        return {noise > kNoisySurface ? kPassesForNoisySurface : 0, noise};
    }
    checkDenoisingPasses(requested);
    return {requested, -1.0};
}

void checkDenoisingPasses(int requested) {
    if (requested != kAutomaticDenoising && (requested < 0 || requested > kMaximumDenoisingPasses)) {
        throw InvalidInput(Problem::aboutParameter(
            Parameter::DenoisingPasses, "must be between 0 (off) and " + std::to_string(kMaximumDenoisingPasses) +
                                            ", or -1 (automatic: only noisy clouds)."));
    }
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
