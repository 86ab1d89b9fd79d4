// Benchmark of the skeleton-driven reconstruction (Section V): time, solver effort and
// peak memory against the grid resolution, on two shapes of known genus:
//   torus gap  a torus scan with 20% of its circumference missing and its ring skeleton
//              (genus 1; a flat domain, about 1/3 of the cube's nodes);
//   cube frame tubes along the 12 edges of a cube and that graph as skeleton (genus 5;
//              a cubic domain, the worst case for a given resolution).
// One child process per case.
//
// usage: bench_reconstruction [RESOLUTION ...]      default: 64 128 256
#include "run_in_child.h"

#include "support/sampled_shapes.h"
#include <pcskeleton/core/openmp_wait_policy.h>
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>

#include <chrono>
#include <cstdlib>
#include <vector>

using namespace pcskeleton;

namespace {

struct Row {
    std::array<int, 3> grid{};
    double unknowns = 0;
    int levels = 0, iterations = 0;
    double residual = 0, setup = 0, solve = 0, extraction = 0, total = 0;
    int genus = -1, triangles = 0;
    bool closed = false;
};

struct Case {
    const char* name;
    int expectedGenus;
    PointList scan;
    SkeletonGraph skeleton;
};

Case makeCase(int shape) {
    if (shape == 0) {
        const double pi = 3.14159265358979323846;
        return {"torus gap", 1,
                shapes::withoutSector(shapes::torus(20000, 1.0, 0.3, 7), Point::Zero(), 0.0, 0.2 * 2 * pi),
                shapes::curveSkeleton(shapes::circle(Point::Zero(), 1.0, 24), 0.3)};
    }
    shapes::Polyline edges;
    for (int a = 0; a < 8; ++a)
        for (int axis = 0; axis < 3; ++axis)
            if (!(a & (1 << axis))) {
                const Point from((a & 1), (a >> 1) & 1, (a >> 2) & 1);
                edges.push_back({from, from + Point::Unit(axis)});
            }
    return {"cube frame", 5, shapes::tube(edges, 0.12, 20000, 7), shapes::curveSkeleton(edges, 0.12)};
}

Row runCase(int shape, int resolution) {
    const Case c = makeCase(shape);
    ReconstructionParameters parameters;
    parameters.resolution = resolution;
    const auto start = std::chrono::steady_clock::now();
    const Reconstruction result = reconstructFromSkeleton(c.scan, c.skeleton, parameters);
    const ReconstructionReport& r = result.report;
    Row row;
    row.total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    row.grid = r.gridNodes;
    row.unknowns = double(r.unknowns);
    row.levels = r.levels;
    row.iterations = r.iterations;
    row.residual = r.relativeResidual;
    row.setup = r.setupSeconds;
    row.solve = r.solveSeconds;
    row.extraction = r.extractionSeconds;
    row.genus = r.topology.genus;
    row.triangles = r.topology.triangles;
    row.closed = r.topology.closedManifold();
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    pcskeleton::restartWithPassiveOpenMpWaits(argv);
    std::vector<int> resolutions;
    for (int a = 1; a < argc; ++a) {
        const int resolution = std::atoi(argv[a]);
        if (resolution < 16 || resolution > 512) {
            std::fprintf(stderr, "usage: bench_reconstruction [RESOLUTION ...]   (each 16-512; default 64 128 256)\n");
            return 2;
        }
        resolutions.push_back(resolution);
    }
    if (resolutions.empty()) resolutions = {64, 128, 256};

    std::printf("Skeleton-driven reconstruction, 20000 points per shape, %ld cores\n", sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("%-10s  %8s  %5s  %15s  %9s  %6s  %5s  %8s  %7s  %7s  %7s  %7s  %5s  %9s  %6s  %9s\n", "shape", "expected", "res", "grid nodes",
                "unknowns", "levels", "iters", "residual", "setup", "solve", "surface", "total", "genus", "triangles",
                "closed", "peak RSS");
    for (int shape = 0; shape < 2; ++shape) {
        for (int resolution : resolutions) {
        Row row;
        double peakMegabytes = 0;
        const Case c = makeCase(shape);
        if (!runInChild([&] { return runCase(shape, resolution); }, row, peakMegabytes)) {
            std::printf("%-10s  %5d  failed\n", c.name, resolution);
            continue;
        }
        std::printf("%-10s  %8d  %5d  %4d x%4d x%4d  %8.2fM  %6d  %5d  %8.1e  %6.2fs  %6.2fs  %6.2fs  %6.2fs  %5d  %9d  %6s  %6.0f MB\n",
                    c.name, c.expectedGenus, resolution, row.grid[0], row.grid[1], row.grid[2], row.unknowns / 1e6, row.levels, row.iterations,
                    row.residual, row.setup, row.solve, row.extraction, row.total, row.genus, row.triangles,
                    row.closed ? "yes" : "NO", peakMegabytes);
        }
    }
    return 0;
}
