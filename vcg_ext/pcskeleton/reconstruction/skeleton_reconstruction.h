// Section V: skeleton-driven reconstruction. The skeleton (possibly edited) says where
// the inside is and what topology the surface has; the points say where the surface is.
//
//   u = argmin  w_smooth ∫(Δu)²  +  w_surface Σ_surface u(p)²
//             + w_skeleton Σ_skeleton (u(p) + d(p))²  +  w_outside Σ_outside (u(p) − φ(p))²
//
// surface: the input points; skeleton: samples along every bone with d the radius
// interpolated between its nodes; outside: grid nodes farther than K radii from the
// skeleton (and the grid's boundary), pulled towards φ = distance to the skeleton minus
// the radius there (positive, the skeleton's own cylindrical estimate of the distance).
// The result is the zero level set of u.
//
// Scale: the energy is evaluated in a frame where the grid's longest side is 1, which
// makes the weights independent of the model's units; the outside term counts nodes at
// the density of the paper's 64-cell grid, so the weights mean the same at any resolution.
#pragma once

#include "pcskeleton/reconstruction/iso_surface.h"
#include "pcskeleton/reconstruction/vertex_fitting.h"
#include "pcskeleton/core/advice.h"
#include "pcskeleton/core/progress.h"
#include "pcskeleton/skeleton/skeleton_graph.h"

#include <array>
#include <string>
#include <vector>

namespace pcskeleton {

struct ReconstructionParameters {
    double smoothWeight = 1.0;     // w1: smoothness of the field
    double surfaceWeight = 5.0;    // w2: the surface passes through the points
    double skeletonWeight = 0.5;   // w3: the field is -radius on the skeleton
    double outsideWeight = 0.005;  // w4: the field is positive far from the skeleton
    double outsideRadii = 4.0;     // K: "far" = more than K radii from the skeleton
    int resolution = 128;          // grid cells along the longest side of the domain
    // The surface gets the skeleton's topology (topology_control.h): handles, bridges and
    // islands the skeleton does not have are cut away. false: the paper's plain fit, whose
    // zero level set may have any topology the data suggests.
    bool keepSkeletonTopology = true;
    // Points whose neighbours scatter across the surface by more than a grid cell weigh
    // less in the surface term (point_weights.h): noise then makes no bumps. false: every
    // point weighs w2, the paper's. On because it brings noisy surfaces closer to the true
    // one and changes nothing on clean ones (docs/benchmarks.md#measurements-behind-the-constants).
    bool adaptToNoise = true;
    // Where data exists the surface's vertices move onto a local fit of the points
    // (vertex_fitting.h), by at most a cell. false: the zero level set as it is.
    bool fitVerticesToPoints = true;

    // The paper's plain fit: no topology guarantee, every point weighing w2, the level set as it is.
    void keepToThePaper() {
        keepSkeletonTopology = false;
        adaptToNoise = false;
        fitVerticesToPoints = false;
    }
};

constexpr int kMinimumResolution = 16;
constexpr int kMaximumResolution = 512;

// Throws InvalidInput naming the first unusable parameter.
void checkReconstructionParameters(const ReconstructionParameters& parameters);

struct ReconstructionWarning {
    enum class Kind {
        PointsFarFromSkeleton,
        SolverNotConverged,
        SurfaceReachedGridEdge,
        NotClosedManifold,
        DataDisagreesWithSkeleton,  // the fit had a handle, bridge or island the skeleton has not
        TopologyDiffersFromSkeleton,
    };
    Kind kind;
    Problem problem;
};

struct ReconstructionReport {
    std::array<int, 3> gridNodes{};
    std::size_t unknowns = 0;
    double cellSize = 0;  // input units
    std::size_t surfaceSamples = 0, skeletonSamples = 0, outsideNodes = 0;
    double surfaceWeightShare = 1.0;  // the surface samples' mean weight, as a share of w2
    int levels = 0, iterations = 0;
    double relativeResidual = 0;
    bool converged = false;
    double setupSeconds = 0, solveSeconds = 0, extractionSeconds = 0;
    SurfaceTopology topology;
    bool topologyControlled = false;
    std::size_t insideNodes = 0, removedNodes = 0;  // the fit's inside, and what was cut from it
    bool verticesFitted = false;
    VertexFittingReport vertexFitting;
    std::vector<ReconstructionWarning> warnings;  // things the user should look at
};
// Several lines for a log: grid, unknowns, solver, time, topology of the result.
std::string describeFindings(const ReconstructionReport& report);
// The findings, then one "warning: ..." line per warning, its remedies worded in `terms`.
std::string describe(const ReconstructionReport& report, const Terms& terms = libraryTerms());

struct Reconstruction {
    TriangleMesh mesh;  // input frame, closed, outward-facing
    ReconstructionReport report;
};

// Throws InvalidInput, with the reason and what to do, for: no points, non-finite
// coordinates, a skeleton without nodes or with a node whose radius is missing (zero,
// negative, not finite), a skeleton that does not describe the points (most points
// farther than K radii from it), bad parameters.
Reconstruction reconstructFromSkeleton(const PointList& points, const SkeletonGraph& skeleton,
                                       const ReconstructionParameters& parameters = {},
                                       const ProgressCallback& progress = {});

}  // namespace pcskeleton
