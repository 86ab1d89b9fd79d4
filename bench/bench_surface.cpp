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
// --poisson measures MeshLab's screened Poisson instead, the reference the reconstruction
// issue set: bench/scripts/screened_poisson.mlx (normals for the point set from 10
// neighbours, then depth 8 and every other setting at MeshLab's default) through the
// system's meshlabserver under xvfb-run; its time includes meshlabserver's start (about
// 0.5 s). Its surface has no skeleton to follow: the topology columns are left empty.
//
// usage: bench_surface [POINTS] [--resolution R] [--shape TEXT] [--data-topology] [--uniform-point-weights]
//                      [--level-set] [--poisson]
//                      [--surface-weight W2] [--smooth-weight W1]
//        POINTS per clean sample (default 6000, as bench_robustness), R the grid (128)
#include "robustness_suite.h"
#include "run_in_child.h"

#include <pcskeleton/core/openmp_wait_policy.h>
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/internal/spatial_index.h>
#include <pcskeleton/internal/stopwatch.h>
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
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

// The vertices of MeshLab's screened Poisson surface of `cloud` (see --poisson above).
PointList screenedPoissonVertices(const PointList& cloud) {
    char folder[] = "/tmp/bench_surface_XXXXXX";
    if (!mkdtemp(folder)) throw std::runtime_error("cannot make a scratch folder");
    const std::string input = std::string(folder) + "/cloud.ply", output = std::string(folder) + "/poisson.ply";
    writePointCloud(cloud, input);
    const std::string command = "xvfb-run -a meshlabserver -i " + input + " -o " + output +
                                " -s " PCSKELETON_POISSON_SCRIPT " >" + folder + "/log.txt 2>&1";
    const bool made = std::system(command.c_str()) == 0 && std::filesystem::exists(output);
    PointList vertices = made ? readPointCloud(output) : PointList{};
    std::filesystem::remove_all(folder);
    if (!made) throw std::runtime_error("meshlabserver's screened Poisson failed");
    return vertices;
}

Row measure(const Subject& subject, const Condition& condition, std::size_t n, const ReconstructionParameters& parameters,
            bool poisson) {
    Row row;
    const PointList cloud = condition.make(subject, n, 11);
    const double diagonal = boundingBox(subject.sample(n, 11)).diagonal().norm();
    Stopwatch stage;
    PointList vertices;
    if (poisson) {
        vertices = screenedPoissonVertices(cloud);
        row.surfaceSeconds = stage.seconds();
        row.skeletonComponents = row.skeletonCycles = row.components = row.genus = -1;
    } else {
        const SkeletonResult skeleton = computeCurveSkeleton(cloud);
        row.skeletonSeconds = stage.seconds();
        const SkeletonTopology expected = analyseTopology(skeleton.skeleton);
        row.skeletonComponents = expected.components;
        row.skeletonCycles = expected.cycles;

        stage.restart();
        Reconstruction surface = reconstructFromSkeleton(cloud, skeleton.skeleton, parameters);
        row.surfaceSeconds = stage.seconds();
        const SurfaceTopology& t = surface.report.topology;
        row.components = t.components;
        row.genus = t.genus;
        row.topologyKept = t.closedManifold() && t.components == expected.components && t.genus == expected.cycles;
        vertices = std::move(surface.mesh.vertices);
    }

    const PointIndex index(cloud);
    std::vector<int> found;
    std::vector<double> distances;
    for (const Point& v : vertices) {
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
        row.withData = 100.0 * double(distances.size()) / double(vertices.size());
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
    bool poisson = false;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--resolution" && a + 1 < argc) parameters.resolution = std::atoi(argv[++a]);
        else if (arg == "--shape" && a + 1 < argc) onlyShape = argv[++a];
        else if (arg == "--data-topology") parameters.keepSkeletonTopology = false;
        else if (arg == "--uniform-point-weights") parameters.adaptToNoise = false;
        else if (arg == "--level-set") parameters.fitVerticesToPoints = false;
        else if (arg == "--poisson") poisson = true;
        else if (arg == "--surface-weight" && a + 1 < argc) parameters.surfaceWeight = std::atof(argv[++a]);
        else if (arg == "--smooth-weight" && a + 1 < argc) parameters.smoothWeight = std::atof(argv[++a]);
        else if (arg.rfind("--", 0) != 0) n = std::strtoull(arg.c_str(), nullptr, 10);
        else {
            std::fprintf(stderr, "usage: bench_surface [POINTS] [--resolution R] [--shape TEXT] [--data-topology] [--uniform-point-weights] [--level-set] [--poisson]\n"
                                 "       [--surface-weight W2] [--smooth-weight W1]\n");
            return 2;
        }
    }
    const std::vector<Subject> subjects = robustnessSubjects();
    if (poisson) {
        std::printf("MeshLab's screened Poisson (depth 8, normals from 10 neighbours), %zu points per clean sample, %ld cores.\n"
                    "Distances to the true surface where data exists, in %% of the diagonal.\n",
                    n, sysconf(_SC_NPROCESSORS_ONLN));
    } else {
        std::printf("Surface from each scan's own skeleton, resolution %d, %s, %s, %s, %zu points per clean sample, %ld cores.\n"
                    "Distances to the true surface where data exists, in %% of the diagonal.\n",
                    parameters.resolution, parameters.keepSkeletonTopology ? "topology guarantee" : "plain fit",
                    parameters.adaptToNoise ? "noise-adapted point weights" : "uniform point weights",
                    parameters.fitVerticesToPoints ? "vertices fitted to the points" : "the level set as it is", n,
                    sysconf(_SC_NPROCESSORS_ONLN));
    }
    std::printf("%-24s %-14s %9s %9s %5s %7s %7s %5s %8s %8s\n", "shape", "condition", "skeleton", "surface", "kept",
                "mean d", "99% d", "data", "skeleton", "surface");
    std::map<std::string, Tally> byCondition;
    for (const Subject& subject : subjects) {
        if (!subject.surfaceDistance || subject.name.find(onlyShape) == std::string::npos) continue;
        for (const Condition& condition : conditions()) {
            if (std::find(kConditions.begin(), kConditions.end(), condition.name) == kConditions.end()) continue;
            Row row;
            double peak = 0;
            if (!runInChild([&] { return measure(subject, condition, n, parameters, poisson); }, row, peak)) {
                std::printf("%-24s %-14s failed\n", subject.name.c_str(), condition.name);
                continue;
            }
            if (poisson) {
                std::printf("%-24s %-14s %9s %9s %5s %7.3f %7.3f %4.0f%% %8s %7.2fs\n", subject.name.c_str(), condition.name,
                            "-", "-", "-", row.meanDistance, row.nearlyMaxDistance, row.withData, "-", row.surfaceSeconds);
            } else {
                std::printf("%-24s %-14s %4d, %2d  %4d, %2d  %5s %7.3f %7.3f %4.0f%% %7.2fs %7.2fs\n", subject.name.c_str(),
                            condition.name, row.skeletonComponents, row.skeletonCycles, row.components, row.genus,
                            row.topologyKept ? "yes" : "NO", row.meanDistance, row.nearlyMaxDistance, row.withData,
                            row.skeletonSeconds, row.surfaceSeconds);
            }
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
        const std::string kept = poisson ? "-" : std::to_string(t.kept) + "/" + std::to_string(t.cases);
        std::printf("%-14s %15s %8.3f %9.2fs %9.2fs\n", name.c_str(), kept.c_str(),
                    t.measured ? t.meanDistance / t.measured : -1.0, t.skeletonSeconds / t.cases, t.surfaceSeconds / t.cases);
    }
    return 0;
}
