// Benchmark of the whole pipeline (contraction, thinning, embedding): time per stage,
// the skeleton's size and topology, and peak memory for sampled tori of growing size
// (the right answer is always one cycle). One child process per case.
//
// usage: bench_skeleton [SIZE ...]      default sizes: 10000 100000 1000000
#include "run_in_child.h"

#include <pcskeleton/curve_skeleton.h>
#include "support/sampled_shapes.h"

#include <chrono>
#include <cstdlib>
#include <vector>

using namespace pcskeleton;

namespace {

struct Row {
    StageSeconds seconds;
    double total = 0;
    int iterations = 0, nodes = 0, cycles = 0;
};

Row runCase(std::size_t n) {
    const PointList cloud = shapes::torus(n, 1.0, 0.3, 7);
    const auto start = std::chrono::steady_clock::now();
    const SkeletonResult result = computeCurveSkeleton(cloud);
    Row row;
    row.total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    row.seconds = result.seconds;
    row.iterations = static_cast<int>(result.contraction.iterations.size());
    const SkeletonTopology t = analyseTopology(result.skeleton);
    row.nodes = t.nodes;
    row.cycles = t.cycles;
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::size_t> sizes;
    for (int a = 1; a < argc; ++a) sizes.push_back(std::strtoull(argv[a], nullptr, 10));
    if (sizes.empty()) sizes = {10000, 100000, 1000000};

    std::printf("Curve skeleton of a sampled torus (1 cycle expected), %ld cores\n", sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("%9s  %5s  %8s  %11s  %8s  %9s  %8s  %5s  %6s  %9s\n", "points", "iters", "1-rings", "contraction",
                "thinning", "embedding", "total", "nodes", "cycles", "peak RSS");
    for (std::size_t n : sizes) {
        Row row;
        double peakMegabytes = 0;
        if (!runInChild([&] { return runCase(n); }, row, peakMegabytes)) {
            std::printf("%9zu  failed\n", n);
            continue;
        }
        const StageSeconds& s = row.seconds;
        std::printf("%9zu  %5d  %7.2fs  %10.2fs  %7.2fs  %8.2fs  %7.2fs  %5d  %6d  %6.0f MB\n", n, row.iterations,
                    s.neighbourhoods, s.contraction, s.thinning, s.embedding, row.total, row.nodes, row.cycles,
                    peakMegabytes);
    }
    return 0;
}
