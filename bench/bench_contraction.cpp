// Benchmark of the contraction (paper steps 1-3): time per stage and peak memory for
// sampled tori of growing size. Each case runs in a child process so that its peak
// resident memory is its own.
//
// usage: bench_contraction [SIZE ...] [--solver cholmod|eigen|both]
//        default sizes: 10000 100000 1000000
#include "run_in_child.h"
#include "size_arguments.h"

#include <pcskeleton/core/openmp_wait_policy.h>
#include <pcskeleton/contraction/laplacian_contraction.h>
#include "support/sampled_shapes.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace pcskeleton;

namespace {

struct Row {
    double neighbourhoods = 0, firstIteration = 0, otherIterations = 0, total = 0;
    int iterations = 0;
};

Row runCase(std::size_t n, LinearSolver solver) {
    const PointList cloud = shapes::torus(n, 1.0, 0.3, 7);
    ContractionParameters parameters;
    parameters.solver = solver;
    const auto start = std::chrono::steady_clock::now();
    LaplacianContraction contraction(cloud, parameters);
    Row row;
    row.neighbourhoods = contraction.neighbourhoodSeconds();
    while (!contraction.finished()) {
        const IterationReport r = contraction.iterate();
        (r.iteration == 1 ? row.firstIteration : row.otherIterations) += r.seconds;
    }
    const PointList result = contraction.contractedPoints();  // mapping back is part of the total
    row.total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    row.iterations = static_cast<int>(contraction.history().size());
    return row;
}

const char* name(LinearSolver s) { return s == LinearSolver::Cholmod ? "CHOLMOD" : "Eigen LDLT"; }

}  // namespace

int main(int argc, char** argv) {
    pcskeleton::restartWithPassiveOpenMpWaits(argv);
    std::vector<std::size_t> sizes;
    std::vector<LinearSolver> solvers = {LinearSolver::Cholmod};
    const char* usage = "bench_contraction [SIZE ...] [--solver cholmod|eigen|both]";
    for (int a = 1; a < argc; ++a) {
        if (!std::strcmp(argv[a], "--help")) {
            std::printf("usage: %s\n", usage);
            return 0;
        } else if (!std::strcmp(argv[a], "--solver")) {
            const std::string s = a + 1 < argc ? argv[++a] : "";
            if (s == "eigen") solvers = {LinearSolver::EigenSimplicial};
            else if (s == "both") solvers = {LinearSolver::Cholmod, LinearSolver::EigenSimplicial};
            else if (s == "cholmod") solvers = {LinearSolver::Cholmod};
            else exitWithUsage("--solver needs cholmod, eigen or both", s.c_str(), usage);
        } else if (const unsigned long long n = pointCount(argv[a])) {
            sizes.push_back(n);
        } else {
            exitWithUsage("not a size or an option", argv[a], usage);
        }
    }
    if (sizes.empty()) sizes = {10000, 100000, 1000000};

    std::printf("Laplacian contraction of a sampled torus, %ld cores\n", sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("%9s  %-10s  %6s  %9s  %9s  %9s  %9s  %9s  %11s\n", "points", "solver", "iters", "1-rings",
                "iter 1", "iters 2+", "total", "s/Mpoint", "peak RSS");
    for (std::size_t n : sizes) {
        for (LinearSolver solver : solvers) {
            Row row;
            double peakMegabytes = 0;
            const bool ok = runInChild([&] { return runCase(n, solver); }, row, peakMegabytes);
            if (!ok) {
                std::printf("%9zu  %-10s  failed\n", n, name(solver));
                continue;
            }
            std::printf("%9zu  %-10s  %6d  %8.2fs  %8.2fs  %8.2fs  %8.2fs  %9.2f  %8.0f MB\n", n, name(solver),
                        row.iterations, row.neighbourhoods, row.firstIteration, row.otherIterations, row.total,
                        row.total / (n / 1e6), peakMegabytes);
            std::fflush(stdout);
        }
    }
    return 0;
}
