// Benchmark of the reconstructed surface (Section V) on the robustness suite's scans: each
// scan's own skeleton by the default pipeline, then the surface from it, compared with the
// shape's true surface (tubes: their walls; libcgal-demo models: their meshes).
//
// Columns: whether the surface has the skeleton's topology (closed, one component per
// skeleton component, genus = the skeleton's cycles); the distance of its vertices to the
// true surface where data exists (vertices within 1% of the diagonal of an input point),
// mean and 99th percentile, in % of the diagonal; the share of vertices where data exists;
// time of the skeleton and of the surface. A summary per condition follows.
//
// usage: bench_surface [POINTS] [--resolution R] [--shape TEXT] [--data-topology] [--uniform-point-weights]
//        POINTS per clean sample (default 6000, as bench_robustness), R the grid (128)
#include "robustness_suite.h"
#include "run_in_child.h"

#include <pcskeleton/core/openmp_wait_policy.h>
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/internal/spatial_index.h>
#include <pcskeleton/internal/stopwatch.h>
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

using namespace pcskeleton;
using namespace pcskeleton::bench;

namespace {

// Where the targets are set: noise, misalignment, partial scans; clean as reference.
const std::vector<std::string> kConditions{"clean",         "noise 1%",     "noise 2%",
                                           "misaligned 1%", "scan 1 view", "scan 4 views"};

struct Row {
    bool topologyKept = false;
    int components = 0, genus = 0, skeletonComponents = 0, skeletonCycles = 0;
    double meanDistance = -1, nearlyMaxDistance = -1, withData = 0;  // % of the diagonal; share in %
    double skeletonSeconds = 0, surfaceSeconds = 0;
};

Row measure(const Subject& subject, const Condition& condition, std::size_t n, const ReconstructionParameters& parameters) {
    Row row;
    const PointList cloud = condition.make(subject, n, 11);
    const double diagonal = boundingBox(subject.sample(n, 11)).diagonal().norm();
    Stopwatch stage;
    const SkeletonResult skeleton = computeCurveSkeleton(cloud);
    row.skeletonSeconds = stage.seconds();
    const SkeletonTopology expected = analyseTopology(skeleton.skeleton);
    row.skeletonComponents = expected.components;
    row.skeletonCycles = expected.cycles;

    stage.restart();
    const Reconstruction surface = reconstructFromSkeleton(cloud, skeleton.skeleton, parameters);
    row.surfaceSeconds = stage.seconds();
    const SurfaceTopology& t = surface.report.topology;
    row.components = t.components;
    row.genus = t.genus;
    row.topologyKept = t.closedManifold() && t.components == expected.components && t.genus == expected.cycles;

    const PointIndex index(cloud);
    std::vector<int> found;
    std::vector<double> distances;
    for (const Point& v : surface.mesh.vertices) {
        index.withinRadius(v, 0.01 * diagonal, found);
        if (!found.empty()) distances.push_back(100.0 * subject.surfaceDistance(v) / diagonal);
    }
    if (!distances.empty()) {
        double sum = 0;
        for (double d : distances) sum += d;
        row.meanDistance = sum / double(distances.size());
        const auto nearlyMax = distances.begin() + std::ptrdiff_t(0.99 * double(distances.size() - 1));
        std::nth_element(distances.begin(), nearlyMax, distances.end());
        row.nearlyMaxDistance = *nearlyMax;
        row.withData = 100.0 * double(distances.size()) / double(surface.mesh.vertices.size());
    }
    return row;
}

struct Tally {
    int cases = 0, kept = 0, measured = 0;
    double meanDistance = 0, skeletonSeconds = 0, surfaceSeconds = 0;
};

}  // namespace

int main(int argc, char** argv) {
    pcskeleton::restartWithPassiveOpenMpWaits(argv);
    std::size_t n = 6000;
    ReconstructionParameters parameters;
    std::string onlyShape;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--resolution" && a + 1 < argc) parameters.resolution = std::atoi(argv[++a]);
        else if (arg == "--shape" && a + 1 < argc) onlyShape = argv[++a];
        else if (arg == "--data-topology") parameters.keepSkeletonTopology = false;
        else if (arg == "--uniform-point-weights") parameters.adaptToNoise = false;
        else if (arg.rfind("--", 0) != 0) n = std::strtoull(arg.c_str(), nullptr, 10);
        else {
            std::fprintf(stderr, "usage: bench_surface [POINTS] [--resolution R] [--shape TEXT] [--data-topology] [--uniform-point-weights]\n");
            return 2;
        }
    }
    const std::vector<Subject> subjects = robustnessSubjects();
    std::printf("Surface from each scan's own skeleton, resolution %d, %s, %s, %zu points per clean sample, %ld cores.\n"
                "Distances to the true surface where data exists, in %% of the diagonal.\n",
                parameters.resolution, parameters.keepSkeletonTopology ? "topology guarantee" : "plain fit",
                parameters.adaptToNoise ? "noise-adapted point weights" : "uniform point weights", n,
                sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("%-24s %-14s %9s %9s %5s %7s %7s %5s %8s %8s\n", "shape", "condition", "skeleton", "surface", "kept",
                "mean d", "99% d", "data", "skeleton", "surface");
    std::map<std::string, Tally> byCondition;
    for (const Subject& subject : subjects) {
        if (!subject.surfaceDistance || subject.name.find(onlyShape) == std::string::npos) continue;
        for (const Condition& condition : conditions()) {
            if (std::find(kConditions.begin(), kConditions.end(), condition.name) == kConditions.end()) continue;
            Row row;
            double peak = 0;
            if (!runInChild([&] { return measure(subject, condition, n, parameters); }, row, peak)) {
                std::printf("%-24s %-14s failed\n", subject.name.c_str(), condition.name);
                continue;
            }
            std::printf("%-24s %-14s %4d, %2d  %4d, %2d  %5s %7.3f %7.3f %4.0f%% %7.2fs %7.2fs\n", subject.name.c_str(),
                        condition.name, row.skeletonComponents, row.skeletonCycles, row.components, row.genus,
                        row.topologyKept ? "yes" : "NO", row.meanDistance, row.nearlyMaxDistance, row.withData,
                        row.skeletonSeconds, row.surfaceSeconds);
            std::fflush(stdout);
            Tally& t = byCondition[condition.name];
            ++t.cases;
            t.kept += row.topologyKept;
            if (row.meanDistance >= 0) t.meanDistance += row.meanDistance, ++t.measured;
            t.skeletonSeconds += row.skeletonSeconds;
            t.surfaceSeconds += row.surfaceSeconds;
        }
    }
    std::printf("\n%-14s %15s %8s %10s %10s\n", "condition", "topology kept", "mean d", "skeleton", "surface");
    for (const std::string& name : kConditions) {
        const Tally& t = byCondition[name];
        if (t.cases == 0) continue;
        std::printf("%-14s %11d/%-3d %8.3f %9.2fs %9.2fs\n", name.c_str(), t.kept, t.cases,
                    t.measured ? t.meanDistance / t.measured : -1.0, t.skeletonSeconds / t.cases, t.surfaceSeconds / t.cases);
    }
    return 0;
}
