#include "pcskeleton/reconstruction/skeleton_reconstruction.h"

#include "pcskeleton/internal/machine_memory.h"
#include "pcskeleton/internal/median.h"
#include "pcskeleton/internal/stopwatch.h"
#include "pcskeleton/reconstruction/field_fitting.h"
#include "pcskeleton/reconstruction/point_weights.h"
#include "pcskeleton/reconstruction/topology_control.h"
#include "pcskeleton/skeleton/skeleton_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace pcskeleton {

namespace {


constexpr int kPaperResolution = 64;          // the paper's grid: 2^6 cells on the longest side
constexpr int kDistanceResolution = 64;       // distances to the skeleton are computed exactly up to here
constexpr double kSkeletonSampleSpacing = 0.25;      // along bones: four samples per paper cell
constexpr double kMarginShare = 0.05;          // empty space around the data, share of the longest side
// A skeleton of the points has its nodes inside their box (re-centred nodes of one-sided
// parts a little outside) and radii well under its diagonal: a node a whole diagonal
// away, or a radius of a whole diagonal, belongs to something else.
constexpr double kFarthestNodeDiagonals = 1.0;
constexpr double kWidestRadiusDiagonals = 1.0;
// Fewer grid cells holding a point than this and the points do not place a surface: the
// field would be the skeleton's tubes alone, however "successful" the solve.
constexpr std::size_t kMinimumOccupiedCells = 32;

// The frame of the paper's grid: positions scaled so that the grid's longest side is 64,
// i.e. lengths are counted in the cells of the paper's 2^6 grid, whatever our resolution.
struct Frame {
    Point origin;  // input position of grid node (0, 0, 0)
    double scale;  // frame = (input - origin) * scale
    Point toFrame(const Point& p) const { return (p - origin) * scale; }
    Point toInput(const Point& p) const { return p / scale + origin; }
};

// The grid spans the points and every node's ball: a node far from the points, or a radius
// far larger than they are, makes it so coarse that the points fall into a few cells. Said
// of the skeleton, which is what is wrong (a stray node, radii of another scale).
void refuseSkeletonBeyondPoints(const PointList& points, const SkeletonGraph& skeleton) {
    const Eigen::AlignedBox3d box = boundingBox(points);
    const double diagonal = box.diagonal().norm();
    if (!(diagonal > 0)) return;  // the points' own problem, said by the grid's check
    std::size_t far = 0, wide = 0, firstFar = 0, firstWide = 0;
    double farthest = 0, widest = 0;
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
        const double away = box.exteriorDistance(skeleton.nodes[n]) / diagonal;
        const double radius = skeleton.radii[n] / diagonal;
        if (away > kFarthestNodeDiagonals && far++ == 0) firstFar = n;
        if (radius > kWidestRadiusDiagonals && wide++ == 0) firstWide = n;
        farthest = std::max(farthest, away);
        widest = std::max(widest, radius);
    }
    std::ostringstream text;
    text.precision(3);
    if (far > 0) {
        text << far << " of " << skeleton.nodeCount() << " skeleton nodes lie far outside the points (first: node "
             << firstFar << "; the farthest " << farthest
             << " bounding-box diagonals of the points away): the skeleton does not describe these points.";
        throw InvalidInput(text.str(), {Remedy::take(Step::DeleteNodes), Remedy::take(Step::ComputeSkeleton)});
    }
    if (wide > 0) {
        text << wide << " of " << skeleton.nodeCount() << " skeleton nodes have a radius larger than the points' "
             << "bounding-box diagonal (first: node " << firstWide << "; the largest " << widest
             << " diagonals): the radii are not these points'.";
        throw InvalidInput(text.str(), {Remedy::take(Step::SetNodeRadii), Remedy::take(Step::ComputeSkeleton)});
    }
}

void checkInputs(const PointList& points, const SkeletonGraph& skeleton) {
    if (points.empty()) throw InvalidInput("The cloud is empty: reconstruction needs the surface samples.");
    rejectNonFinite(points, "points", Remedy::take(Step::RemoveNonFinitePoints));
    if (skeleton.nodes.empty())
        throw InvalidInput("The skeleton has no nodes.", {Remedy::take(Step::ComputeSkeleton)});
    rejectNonFinite(skeleton.nodes, "skeleton nodes", Remedy::take(Step::DeleteNodes));
    if (skeleton.radii.size() != skeleton.nodes.size())
        throw InvalidInput("The skeleton has no radius per node.", {Remedy::take(Step::ComputeSkeleton)});
    int missing = 0, first = -1;
    for (std::size_t n = 0; n < skeleton.radii.size(); ++n)
        if (!isPositiveFinite(skeleton.radii[n]) && missing++ == 0) first = int(n);
    if (missing > 0)
        throw InvalidInput(std::to_string(missing) + " of " + std::to_string(skeleton.nodeCount()) +
                           " skeleton nodes have no radius (zero, negative or not a number; first: node " +
                           std::to_string(first) +
                           "). The radius is the field's depth inside the shape.",
                           {Remedy::take(Step::SetNodeRadii)});
    const std::string violation = invariantViolation(skeleton);
    if (!violation.empty()) throw InvalidInput("The skeleton is not valid: " + violation);
    refuseSkeletonBeyondPoints(points, skeleton);
}

// The number of grid cells holding at least one point: the distinct points as the grid sees them.
std::size_t occupiedCells(const PointList& framePoints, const FieldGrid& grid) {
    std::vector<long long> cells;
    cells.reserve(framePoints.size());
    for (const Point& p : framePoints) {
        long long cell = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const long long i = std::llround((p[axis] - grid.origin[axis]) / grid.spacing);
            cell = cell * (grid.nodes[axis] + 1) + std::clamp<long long>(i, 0, grid.nodes[axis]);
        }
        cells.push_back(cell);
    }
    std::sort(cells.begin(), cells.end());
    return std::size_t(std::unique(cells.begin(), cells.end()) - cells.begin());
}

void refuseTooFewDistinctPoints(const PointList& framePoints, const FieldGrid& grid) {
    const std::size_t cells = occupiedCells(framePoints, grid);
    if (cells >= kMinimumOccupiedCells) return;
    throw InvalidInput("The cloud has " + std::to_string(cells) + " distinct point" + (cells == 1 ? "" : "s") +
                       " at the grid's resolution (" + std::to_string(framePoints.size()) +
                       " points in all); the surface needs at least " + std::to_string(kMinimumOccupiedCells) +
                       " to be placed. Use the scan the skeleton was computed from as the points.");
}

// The box holding the points and every node's ball, with a margin, as a grid whose cell
// counts allow repeated halving (the multigrid levels).
FieldGrid domainGrid(const PointList& points, const SkeletonGraph& skeleton, int resolution, Frame& frame) {
    Eigen::AlignedBox3d box = boundingBox(points);
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
        box.extend(skeleton.nodes[n] - Point::Constant(skeleton.radii[n]));
        box.extend(skeleton.nodes[n] + Point::Constant(skeleton.radii[n]));
    }
    const Point size = box.sizes();
    const double longest = std::max(size.maxCoeff(), 1e-12);
    const int marginCells = std::max(2, int(std::ceil(kMarginShare * resolution)));
    const double spacing = longest / (resolution - 2 * marginCells);
    int halvings = 0;
    while ((resolution >> (halvings + 1)) >= 8) ++halvings;
    const int multiple = 1 << halvings;
    FieldGrid grid;
    Point extent;
    for (int axis = 0; axis < 3; ++axis) {
        int cells = int(std::ceil(size[axis] / spacing - 1e-9)) + 2 * marginCells;
        cells = (cells + multiple - 1) / multiple * multiple;
        grid.nodes[axis] = cells + 1;
        extent[axis] = cells * spacing;
    }
    frame.origin = box.center() - 0.5 * extent;
    frame.scale = kPaperResolution / (resolution * spacing);
    grid.origin = Point::Zero();
    grid.spacing = double(kPaperResolution) / resolution;
    return grid;
}

// Measured peak: about 160 bytes per grid node (solution, constraints, multigrid levels).
// Refusing beats being killed by the kernel half-way.
void refuseGridLargerThanMemory(const FieldGrid& grid) {
    constexpr double kBytesPerNode = 170;
    const double needed = kBytesPerNode * double(grid.size());
    const MemoryAllowance allowance = usableMemory();
    if (allowance.bytes > 0 && needed > allowance.bytes) {
        std::ostringstream text;
        text.precision(2);
        text << "A grid of " << grid.nodes[0] << " x " << grid.nodes[1] << " x " << grid.nodes[2] << " nodes needs about "
             << needed / 1e9 << " GB of memory, more than the " << allowance.bytes / 1e9 << " GB that "
             << allowance.limit << " leaves: lower the grid resolution.";
        throw InvalidInput(text.str());
    }
}

SkeletonGraph skeletonInFrame(const SkeletonGraph& skeleton, const Frame& frame) {
    SkeletonGraph result;
    result.edges = skeleton.edges;
    for (const Point& p : skeleton.nodes) result.nodes.push_back(frame.toFrame(p));
    for (double r : skeleton.radii) result.radii.push_back(r * frame.scale);
    return result;
}

// Most points must lie within K radii of the skeleton, or the skeleton is another shape's.
double shareOfPointsFarFromSkeleton(const PointList& framePoints, const SkeletonDistance& distance, double outsideRadii) {
    const std::size_t step = std::max<std::size_t>(1, framePoints.size() / 20000);
    std::size_t checked = 0, far = 0;
    for (std::size_t i = 0; i < framePoints.size(); i += step, ++checked) {
        const SkeletonProximity near = distance.nearest(framePoints[i]);
        if (near.distance > outsideRadii * near.radius) ++far;
    }
    return double(far) / double(checked);
}

void addSkeletonSamples(const SkeletonGraph& skeleton, double weight, std::vector<PointConstraint>& constraints) {
    for (std::size_t n = 0; n < skeleton.nodeCount(); ++n)
        constraints.push_back({skeleton.nodes[n], -skeleton.radii[n], weight});
    for (const Edge& e : skeleton.edges) {
        const Point a = skeleton.nodes[e[0]], b = skeleton.nodes[e[1]];
        const int samples = int(std::ceil((b - a).norm() / kSkeletonSampleSpacing)) - 1;
        for (int s = 1; s <= samples; ++s) {
            const double t = double(s) / (samples + 1);
            constraints.push_back({(1 - t) * a + t * b, -((1 - t) * skeleton.radii[e[0]] + t * skeleton.radii[e[1]]), weight});
        }
    }
}

// φ (distance to the skeleton minus the radius there) and the outside test at every node
// of `grid`: computed exactly on the coarsest grid of at least kDistanceResolution cells,
// interpolated on finer ones (both are 1-Lipschitz, so the interpolation error is a
// fraction of a coarse cell, far below K radii).
struct SkeletonDistanceField {
    std::vector<double> cylindrical;  // φ
    std::vector<double> beyondOutside;  // distance − K·radius: > 0 means outside
};

SkeletonDistanceField skeletonDistanceField(const FieldGrid& grid, const SkeletonDistance& distance, double outsideRadii) {
    std::vector<FieldGrid> chain{grid};
    while (chain.back().canCoarsen() &&
           *std::max_element(chain.back().nodes.begin(), chain.back().nodes.end()) - 1 > 2 * kDistanceResolution)
        chain.push_back(chain.back().coarser());
    const FieldGrid& exact = chain.back();
    SkeletonDistanceField field{std::vector<double>(exact.size()), std::vector<double>(exact.size())};
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < exact.nodes[2]; ++k)
        for (int j = 0; j < exact.nodes[1]; ++j)
            for (int i = 0; i < exact.nodes[0]; ++i) {
                const SkeletonProximity near = distance.nearest(exact.position(i, j, k));
                field.cylindrical[exact.index(i, j, k)] = near.distance - near.radius;
                field.beyondOutside[exact.index(i, j, k)] = near.distance - outsideRadii * near.radius;
            }
    for (std::size_t level = chain.size() - 1; level > 0; --level) {
        field.cylindrical = interpolateToFiner(chain[level], chain[level - 1], field.cylindrical);
        field.beyondOutside = interpolateToFiner(chain[level], chain[level - 1], field.beyondOutside);
    }
    return field;
}

// Marching cubes closes the surface only if the grid's boundary is outside.
std::size_t closeAtBoundary(const FieldGrid& grid, std::vector<double>& values) {
    std::size_t opened = 0;
    for (int k = 0; k < grid.nodes[2]; ++k)
        for (int j = 0; j < grid.nodes[1]; ++j)
            for (int i = 0; i < grid.nodes[0]; ++i)
                if (grid.isBoundary(i, j, k) && values[grid.index(i, j, k)] <= 0) {
                    values[grid.index(i, j, k)] = grid.spacing;
                    ++opened;
                }
    return opened;
}

}  // namespace

void checkReconstructionParameters(const ReconstructionParameters& p) {
    auto require = [](bool ok, Parameter parameter, const std::string& requirement) {
        if (!ok) throw InvalidInput(Problem::aboutParameter(parameter, requirement));
    };
    require(isPositiveFinite(p.smoothWeight), Parameter::SmoothWeight, "must be positive.");
    require(isPositiveFinite(p.surfaceWeight), Parameter::SurfaceWeight,
            "must be positive: the points place the surface.");
    require(p.skeletonWeight >= 0 && std::isfinite(p.skeletonWeight), Parameter::SkeletonWeight, "must be 0 or more.");
    require(p.outsideWeight >= 0 && std::isfinite(p.outsideWeight), Parameter::OutsideWeight, "must be 0 or more.");
    require(p.outsideRadii > 1 && std::isfinite(p.outsideRadii), Parameter::OutsideDistance,
            "must be more than 1: the outside starts beyond the skeleton's tube.");
    require(p.resolution >= kMinimumResolution && p.resolution <= kMaximumResolution, Parameter::Resolution,
            "must be between " + std::to_string(kMinimumResolution) + " and " + std::to_string(kMaximumResolution) +
                " cells.");
}

Reconstruction reconstructFromSkeleton(const PointList& points, const SkeletonGraph& skeleton,
                                       const ReconstructionParameters& parameters, const ProgressCallback& progress) {
    checkReconstructionParameters(parameters);
    checkInputs(points, skeleton);
    const Stopwatch setup;
    Reconstruction result;
    ReconstructionReport& summary = result.report;
    const double outsideRadii = parameters.outsideRadii;

    report(progress, 0, "Setting up the field");
    Frame frame{};
    const FieldGrid grid = domainGrid(points, skeleton, parameters.resolution, frame);
    refuseGridLargerThanMemory(grid);
    summary.gridNodes = grid.nodes;
    summary.unknowns = grid.size();
    summary.cellSize = grid.spacing / frame.scale;
    PointList framePoints;
    framePoints.reserve(points.size());
    for (const Point& p : points) framePoints.push_back(frame.toFrame(p));
    const SkeletonGraph frameSkeleton = skeletonInFrame(skeleton, frame);
    const SkeletonDistance distance(frameSkeleton);

    const double farShare = shareOfPointsFarFromSkeleton(framePoints, distance, outsideRadii);
    std::ostringstream farText;
    farText << int(std::round(100 * farShare)) << "% of the points are farther than K = " << outsideRadii
            << " radii from the skeleton";
    if (farShare > 0.5)
        throw InvalidInput(farText.str() + ": the skeleton does not describe these points.",
                           {Remedy::take(Step::ComputeSkeleton), Remedy::take(Step::SetNodeRadii),
                            Remedy::raise(Parameter::OutsideDistance)});
    refuseTooFewDistinctPoints(framePoints, grid);
    if (farShare > 0.05)
        summary.warnings.push_back({ReconstructionWarning::Kind::PointsFarFromSkeleton,
                                    {farText.str() + ": the surface there only follows the points",
                                     {Remedy::raise(Parameter::OutsideDistance), Remedy::take(Step::SetNodeRadii)}}});

    FieldProblem problem;
    problem.grid = grid;
    problem.smoothnessWeight = parameters.smoothWeight;
    problem.pointConstraints.reserve(points.size());
    if (parameters.adaptToNoise) {
        const SurfacePointWeights weights = noiseAdaptedWeights(framePoints, grid.spacing, parameters.surfaceWeight);
        for (std::size_t i = 0; i < framePoints.size(); ++i)
            problem.pointConstraints.push_back({framePoints[i], 0.0, weights.weight[i]});
        summary.surfaceWeightShare = weights.meanShare;
    } else {
        for (const Point& p : framePoints) problem.pointConstraints.push_back({p, 0.0, parameters.surfaceWeight});
    }
    summary.surfaceSamples = points.size();
    if (parameters.skeletonWeight > 0) addSkeletonSamples(frameSkeleton, parameters.skeletonWeight, problem.pointConstraints);
    summary.skeletonSamples = problem.pointConstraints.size() - points.size();

    const SkeletonDistanceField skeletonField = skeletonDistanceField(grid, distance, outsideRadii);
    // A node stands for spacing³ paper cells: the outside term means the same at any resolution.
    const double outsideNodeWeight = parameters.outsideWeight * std::pow(grid.spacing, 3);
    // The grid's boundary is ours, not the paper's: held firmly at the skeleton's distance
    // estimate (as stiff as a node's smoothness term). Left weak, the boundary nodes form
    // near-free harmonic modes that no smoother or coarse grid can correct.
    const double boundaryWeight = 36 * parameters.smoothWeight / grid.spacing;
    problem.nodeWeight.assign(grid.size(), 0.0);
    problem.nodeValue.assign(grid.size(), 0.0);
    for (int k = 0; k < grid.nodes[2]; ++k)
        for (int j = 0; j < grid.nodes[1]; ++j)
            for (int i = 0; i < grid.nodes[0]; ++i) {
                const std::size_t n = grid.index(i, j, k);
                const bool boundary = grid.isBoundary(i, j, k);
                if (!boundary && skeletonField.beyondOutside[n] <= 0) continue;
                problem.nodeWeight[n] = boundary ? boundaryWeight : outsideNodeWeight;
                problem.nodeValue[n] = std::max(skeletonField.cylindrical[n], grid.spacing);
                summary.outsideNodes += !boundary;
            }
    summary.setupSeconds = setup.seconds();

    const Stopwatch solveTime;
    FieldSolveReport solve;
    std::vector<double> field =
        solveField(problem, skeletonField.cylindrical, FieldSolverOptions{}, solve, progressRange(progress, 10, 85));
    problem = FieldProblem{};  // the constraints are no longer needed: free them before extraction
    summary.levels = solve.levels;
    summary.iterations = solve.iterations;
    summary.relativeResidual = solve.relativeResidual;
    summary.converged = solve.converged;
    summary.solveSeconds = solveTime.seconds();
    if (!solve.converged)
        summary.warnings.push_back({ReconstructionWarning::Kind::SolverNotConverged,
                                    {"the solver stopped before reaching its tolerance; the surface may be rough.", {}}});

    report(progress, 85, "Extracting the surface");
    const Stopwatch extraction;
    if (const std::size_t opened = closeAtBoundary(grid, field))
        summary.warnings.push_back({ReconstructionWarning::Kind::SurfaceReachedGridEdge,
                                    {"the surface reached the edge of the grid at " + std::to_string(opened) +
                                         " nodes and was closed there",
                                     {Remedy::raise(Parameter::OutsideWeight)}}});
    if (parameters.keepSkeletonTopology) {
        const TopologyControl control = constrainToSkeletonTopology(grid, frameSkeleton, field);
        summary.topologyControlled = true;
        summary.insideNodes = control.insideNodes;
        summary.removedNodes = control.removedNodes;
        // A group of cut nodes worth a look: at least a quarter of a typical bone's cross-
        // section (a handle cut across a real tube), not a noise tunnel of a few nodes.
        const double typicalRadius = median(frameSkeleton.radii) / grid.spacing;  // in cells
        const double worthALook = 0.25 * 3.14159265358979323846 * typicalRadius * typicalRadius;
        if (control.largestRemoval > 0 && double(control.largestRemoval) >= worthALook) {
            const Point where = frame.toInput(control.largestRemovalCentre);
            std::ostringstream text;
            text.precision(3);
            text << "the points suggest a handle, bridge or part the skeleton does not have near (" << where.x()
                 << ", " << where.y() << ", " << where.z() << "); it was cut away (" << control.largestRemoval
                 << " grid nodes). If the shape has a loop or a part there, add it to the skeleton";
            summary.warnings.push_back({ReconstructionWarning::Kind::DataDisagreesWithSkeleton,
                                        {text.str(), {Remedy::turnOff(Parameter::SkeletonTopology)}}});
        }
    }
    result.mesh = extractZeroLevelSet(grid, field);
    if (result.mesh.triangles.empty())
        throw InvalidInput("The field has no zero crossing: no surface was found. The skeleton radii must be close to "
                           "the shape's thickness.",
                           {Remedy::take(Step::SetNodeRadii), Remedy::raise(Parameter::SurfaceWeight)});
    if (parameters.fitVerticesToPoints) {
        summary.verticesFitted = true;
        summary.vertexFitting = fitVerticesToPoints(result.mesh, framePoints, grid.spacing);
    }
    for (Point& v : result.mesh.vertices) v = frame.toInput(v);
    summary.topology = analyseSurface(result.mesh);
    const SkeletonTopology wanted = analyseTopology(skeleton.nodeCount(), skeleton.edges);
    if (parameters.keepSkeletonTopology &&
        (summary.topology.components != wanted.components || summary.topology.genus != wanted.cycles))
        summary.warnings.push_back({ReconstructionWarning::Kind::TopologyDiffersFromSkeleton,
                                    {"the surface has " + describe(summary.topology) + ", the skeleton " +
                                         std::to_string(wanted.components) + " component(s) and " +
                                         std::to_string(wanted.cycles) + " cycle(s): the grid is too coarse for "
                                         "the skeleton's detail",
                                     {Remedy::raise(Parameter::Resolution)}}});
    if (!summary.topology.closedManifold())
        summary.warnings.push_back({ReconstructionWarning::Kind::NotClosedManifold,
                                    {"the surface is not a closed 2-manifold: " + describe(summary.topology), {}}});
    summary.extractionSeconds = extraction.seconds();
    report(progress, 100, "Surface reconstructed");
    return result;
}

std::string describeFindings(const ReconstructionReport& r) {
    std::ostringstream text;
    text.precision(3);
    text << "grid " << r.gridNodes[0] << " x " << r.gridNodes[1] << " x " << r.gridNodes[2] << " nodes (" << r.unknowns
         << " unknowns, cell " << r.cellSize << "), " << r.levels << " multigrid levels\n"
         << "constraints: " << r.surfaceSamples << " surface samples (mean weight " << std::setprecision(0)
         << std::fixed << 100.0 * r.surfaceWeightShare << "% of w2), " << r.skeletonSamples << " skeleton samples, "
         << r.outsideNodes << " outside nodes\n"
         << "solver: " << r.iterations << " iterations, relative residual " << std::scientific << r.relativeResidual
         << std::fixed << std::setprecision(2) << (r.converged ? "" : " (not converged)") << "\n"
         << "time: setup " << r.setupSeconds << " s, solve " << r.solveSeconds << " s, surface "
         << r.extractionSeconds << " s\n"
         << "result: " << describe(r.topology);
    if (r.topologyControlled) {
        const bool reached = std::none_of(r.warnings.begin(), r.warnings.end(), [](const ReconstructionWarning& w) {
            return w.kind == ReconstructionWarning::Kind::TopologyDiffersFromSkeleton;
        });
        text << "\ntopology: " << (reached ? "the skeleton's" : "held to the skeleton's where the grid allows (see the warning)")
             << ", " << r.removedNodes << " of the fit's " << r.insideNodes << " inside grid nodes cut away";
    }
    if (r.verticesFitted)
        text << "\nfit to the points: " << r.vertexFitting.moved << " vertices moved, by " << r.vertexFitting.meanMove
             << " cells on average";
    if (r.verticesFitted && r.vertexFitting.undone > 0)
        text << " (" << r.vertexFitting.undone << " moves undone: they turned a triangle over)";
    return text.str();
}

std::string describe(const ReconstructionReport& r, const Terms& terms) {
    std::string text = describeFindings(r);
    for (const ReconstructionWarning& w : r.warnings) text += "\nwarning: " + describe(w.problem, terms);
    return text;
}

}  // namespace pcskeleton
