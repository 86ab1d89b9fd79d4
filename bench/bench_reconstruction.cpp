// Benchmark of the skeleton-driven reconstruction (Section V): time, solver effort and
// peak memory against the grid resolution, on a torus scan with 20% of its circumference
// missing and its ring skeleton (the right answer is genus 1). One child process per case.
//
// usage: bench_reconstruction [RESOLUTION ...]      default: 64 128 256
#include "run_in_child.h"

#include <pcskeleton/sampled_shapes.h>
#include <pcskeleton/skeleton_reconstruction.h>

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

Row runCase(int resolution) {
    const double pi = 3.14159265358979323846;
    const PointList scan = shapes::withoutSector(shapes::torus(20000, 1.0, 0.3, 7), Point::Zero(), 0.0, 0.2 * 2 * pi);
    const SkeletonGraph ring = shapes::curveSkeleton(shapes::circle(Point::Zero(), 1.0, 24), 0.3);
    ReconstructionParameters parameters;
    parameters.resolution = resolution;
    const auto start = std::chrono::steady_clock::now();
    const Reconstruction result = reconstructFromSkeleton(scan, ring, parameters);
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
    std::vector<int> resolutions;
    for (int a = 1; a < argc; ++a) resolutions.push_back(std::atoi(argv[a]));
    if (resolutions.empty()) resolutions = {64, 128, 256};

    std::printf("Reconstruction of a torus scan (20000 points, 20%% of the ring missing) from its ring skeleton\n"
                "(genus 1 expected), %ld cores\n",
                sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("%5s  %15s  %9s  %6s  %5s  %8s  %7s  %7s  %7s  %7s  %5s  %9s  %6s  %9s\n", "res", "grid nodes",
                "unknowns", "levels", "iters", "residual", "setup", "solve", "surface", "total", "genus", "triangles",
                "closed", "peak RSS");
    for (int resolution : resolutions) {
        Row row;
        double peakMegabytes = 0;
        if (!runInChild([&] { return runCase(resolution); }, row, peakMegabytes)) {
            std::printf("%5d  failed\n", resolution);
            continue;
        }
        std::printf("%5d  %4d x%4d x%4d  %8.2fM  %6d  %5d  %8.1e  %6.2fs  %6.2fs  %6.2fs  %6.2fs  %5d  %9d  %6s  %6.0f MB\n",
                    resolution, row.grid[0], row.grid[1], row.grid[2], row.unknowns / 1e6, row.levels, row.iterations,
                    row.residual, row.setup, row.solve, row.extraction, row.total, row.genus, row.triangles,
                    row.closed ? "yes" : "NO", peakMegabytes);
    }
    return 0;
}
