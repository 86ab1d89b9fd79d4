// A denoised working copy of the cloud, whose 1-rings and contraction replace those of the
// points as given (the skeleton's node positions and radii still come from the points as
// given): each point moved onto the plane fitted (PCA) to its k nearest neighbours, once
// per pass. Noise across the surface shrinks by about the square root of k each pass;
// without it, noisy points leave spurs, split ends and false loops. Not in the paper.
//
// A clean surface needs none, and on a coarse sampling the planes cut corners (a coarse
// figure eight loses a hole), so by default the cloud is denoised only when it is noisy:
// when surfaceNoise() says so.
#pragma once

#include "pcskeleton/core/point.h"

namespace pcskeleton {

// The surface noise of a cloud, scale-free: the median, over every 7th point, of the RMS
// residual of a quadratic height field fitted to the point's k nearest neighbours, over
// the neighbourhood's RMS extent. A quadric follows the curvature of a clean surface, even
// a coarse one, so the measure stays low there; its values on clean and noisy clouds, and
// the threshold below: docs/benchmarks.md#measurements-behind-the-constants.
double surfaceNoise(const PointList& points, int neighbours);

inline constexpr double kNoisySurface = 0.25;    // surfaceNoise() above this: denoise
inline constexpr int kAutomaticDenoising = -1;   // denoisingPasses: decide by surfaceNoise()
inline constexpr int kPassesForNoisySurface = 2;
inline constexpr int kMaximumDenoisingPasses = 10;

struct DenoisingChoice {
    int passes = 0;
    double surfaceNoise = -1;  // -1 when not measured (passes given)
};
// `requested` passes (0..10), or for kAutomaticDenoising kPassesForNoisySurface when the
// cloud is noisy and none otherwise. Other values are refused (InvalidInput).
DenoisingChoice chooseDenoising(const PointList& points, int neighbours, int requested);
// Throws InvalidInput unless `requested` is one chooseDenoising takes.
void checkDenoisingPasses(int requested);

// passes = 0 returns the points unchanged.
PointList denoisedCopy(const PointList& points, int neighbours, int passes);

}  // namespace pcskeleton
