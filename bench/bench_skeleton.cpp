// Benchmark of the whole pipeline as a user runs it: reading a binary PLY file, then the
// skeleton (multi-resolution subsample, 1-rings, contraction, thinning, embedding,
// finishing), with time per stage ('outliers', the outlier detection over the whole cloud,
// is part of 'subsample'), the skeleton's topology and peak memory per stage, for
// sampled tori of growing size (the right answer is always one cycle). A stage's peak is
// the resident set's high-water mark over the stage alone: it is reset (Linux's
// /proc/self/clear_refs) as each stage starts, the stages told apart by their progress
// messages.
// The clouds are generated at run time into a temporary folder (10M points: 240 MB) and
// deleted afterwards. One child process per step, so each peak is the case's own.
//
// With --outliers SHARE, that share of the points again is added as outliers spread
// uniformly over the torus's box (tests/support/scan_simulation.h), and the table counts
// the outliers that got a node and the torus's points that did not.
//
// usage: bench_skeleton [SIZE ...] [--full-resolution] [--outliers SHARE]
//        default sizes: 10000 100000 1000000 10000000
#include "run_in_child.h"
#include "size_arguments.h"

#include <pcskeleton/core/openmp_wait_policy.h>
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/io/point_cloud_io.h>
#include "support/sampled_shapes.h"
#include "support/scan_simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace pcskeleton;

namespace {

enum Stage { Reading, Subsampling, Neighbourhoods, Contraction, ThinningAndFinishing, kStages };
constexpr const char* kStageNames[kStages] = {"read", "subsample", "1-rings", "contract", "thin+finish"};

struct Row {
    double reading = 0, total = 0;
    double outliers = 0;  // part of subsampling: outlier detection over the whole cloud
    StageSeconds seconds;
    double stagePeakMegabytes[kStages] = {};
    std::size_t contracted = 0;
    int iterations = 0, nodes = 0, cycles = 0;
    bool everyPointHasNode = false;
    std::size_t surfaceWithoutNode = 0, outliersWithNode = 0;
};

double peakResidentMegabytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
    }
    return 0;
}

// Starts a new high-water mark at the current resident set; false where the kernel cannot.
bool resetPeakResident() {
    std::ofstream clear("/proc/self/clear_refs");
    return bool(clear << "5" << std::flush);
}

// The stage a progress message belongs to, by the pipeline's wording.
Stage stageOf(const char* what) {
    const std::string message = what;
    if (message.rfind("Multi-resolution", 0) == 0) return Subsampling;
    if (message.rfind("Neighbourhoods", 0) == 0 || message.rfind("Denois", 0) == 0) return Neighbourhoods;
    if (message.rfind("Contracting", 0) == 0) return Contraction;
    return ThinningAndFinishing;
}

// The peak of each stage, from progress messages: a stage ends when the next one's first
// message arrives.
class StagePeaks {
public:
    explicit StagePeaks(double* peaks) : peaks_(peaks) {}
    void enter(Stage stage) {
        if (stage == current_) return;
        peaks_[current_] = std::max(peaks_[current_], peakResidentMegabytes());
        resetPeakResident();
        current_ = stage;
    }
    void finish() { peaks_[current_] = std::max(peaks_[current_], peakResidentMegabytes()); }

private:
    double* peaks_;
    Stage current_ = Reading;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The torus's points come first in the file, `surfacePoints` of them; the outliers follow.
Row runCase(const std::string& file, const SkeletonParameters& parameters, std::size_t surfacePoints) {
    Row row;
    const auto start = std::chrono::steady_clock::now();
    const PointList cloud = readPointCloud(file);
    row.reading = secondsSince(start);
    StagePeaks peaks(row.stagePeakMegabytes);
    // Outlier detection runs from the first multi-resolution message to the one that starts the grid.
    std::chrono::steady_clock::time_point outliersStart{};
    const SkeletonResult result = computeCurveSkeleton(cloud, parameters, [&](int, const char* what) {
        peaks.enter(stageOf(what));
        const std::string message = what;
        if (message.rfind("Multi-resolution: outliers", 0) == 0) outliersStart = std::chrono::steady_clock::now();
        if (message == "Multi-resolution: subsample" && row.outliers == 0) row.outliers = secondsSince(outliersStart);
    });
    peaks.finish();
    row.total = secondsSince(start);
    row.seconds = result.seconds;
    row.contracted = result.quality.points;
    row.iterations = static_cast<int>(result.contraction.iterations.size());
    const SkeletonTopology t = analyseTopology(result.skeleton);
    row.nodes = t.nodes;
    row.cycles = t.cycles;
    row.everyPointHasNode = result.skeleton.pointNode.size() == cloud.size();
    for (int node : result.skeleton.pointNode) row.everyPointHasNode &= node >= 0;
    for (std::size_t i = 0; i < result.skeleton.pointNode.size(); ++i) {
        const bool hasNode = result.skeleton.pointNode[i] >= 0;
        if (i < surfacePoints) row.surfaceWithoutNode += !hasNode;
        else row.outliersWithNode += hasNode;
    }
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    pcskeleton::restartWithPassiveOpenMpWaits(argv);
    std::vector<std::size_t> sizes;
    SkeletonParameters parameters;
    double outlierShare = 0.0;
    const char* usage = "bench_skeleton [SIZE ...] [--full-resolution] [--outliers SHARE]";
    for (int a = 1; a < argc; ++a) {
        if (!std::strcmp(argv[a], "--help")) {
            std::printf("usage: %s\n", usage);
            return 0;
        } else if (std::strcmp(argv[a], "--full-resolution") == 0) {
            parameters.resolution.maxContractedPoints = 0;
        } else if (std::strcmp(argv[a], "--outliers") == 0) {
            char* end = nullptr;
            if (a + 1 < argc) outlierShare = std::strtod(argv[++a], &end);
            if (end == nullptr || *end != '\0' || !(outlierShare > 0 && outlierShare <= 10)) {
                exitWithUsage("--outliers needs a share of the points from 0 to 10", argv[a], usage);
            }
        } else if (const unsigned long long n = pointCount(argv[a])) {
            sizes.push_back(n);
        } else {
            exitWithUsage("not a size or an option", argv[a], usage);
        }
    }
    if (sizes.empty()) sizes = {10000, 100000, 1000000, 10000000};
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("bench_skeleton_" + std::to_string(getpid()));
    std::filesystem::create_directories(folder);

    std::printf("Curve skeleton of a sampled torus read from a binary PLY file (1 cycle expected), %s, %ld cores.\n"
                "Peak memory (MB): the resident set's highest during each stage; 'peak' is the whole run's.\n",
                parameters.resolution.maxContractedPoints == 0 ? "full resolution" : "default pipeline",
                sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("%9s %8s %7s %7s %8s %8s %8s %6s %6s %5s %8s %6s %6s", "points", "contracted", "read", "subsample",
                "outliers", "1-rings", "contract", "thin", "finish", "iters", "total", "nodes", "cycles");
    for (const char* stage : kStageNames) std::printf(" %11s", stage);
    std::printf(" %7s", "peak");
    if (outlierShare > 0) std::printf("  outliers with a node, torus points without");
    std::printf("\n");
    if (!resetPeakResident()) std::printf("(this kernel cannot reset the high-water mark: each stage's peak includes the earlier ones')\n");
    for (std::size_t n : sizes) {
        const std::string file = (folder / ("torus" + std::to_string(n) + ".ply")).string();
        int written = 0;
        double unused = 0;
        const bool generated = runInChild(
            [&] {
                const PointList torus = shapes::torus(n, 1.0, 0.3, 7);
                writePointCloud(outlierShare > 0 ? shapes::withOutliers(torus, outlierShare, 7) : torus, file);
                return 1;
            },
            written, unused);
        Row row;
        double peakMegabytes = 0;
        if (!generated || !runInChild([&] { return runCase(file, parameters, n); }, row, peakMegabytes)) {
            std::printf("%9zu  failed\n", n);
        } else {
            const StageSeconds& s = row.seconds;
            std::printf("%9zu %10zu %6.2fs %8.2fs %7.2fs %7.2fs %7.2fs %5.2fs %5.2fs %5d %7.2fs %6d %6d", n, row.contracted,
                        row.reading, s.subsampling, row.outliers, s.neighbourhoods, s.contraction, s.thinning + s.embedding,
                        s.finishing, row.iterations, row.total, row.nodes, row.cycles);
            // The child's own maximum would miss the stages before the last reset.
            double wholeRun = 0;
            for (double peak : row.stagePeakMegabytes) {
                if (peak > 0) std::printf(" %11.0f", peak);
                else std::printf(" %11s", "-");  // the stage did not run (no subsample below the threshold)
                wholeRun = std::max(wholeRun, peak);
            }
            std::printf(" %7.0f", std::max(wholeRun, peakMegabytes));
            if (outlierShare > 0) {
                const auto outliers = std::size_t(std::round(outlierShare * double(n)));
                std::printf("  %zu of %zu, %zu", row.outliersWithNode, outliers, row.surfaceWithoutNode);
            }
            std::printf("%s\n", row.everyPointHasNode || outlierShare > 0 ? "" : "  (some points without a node)");
        }
        std::filesystem::remove(file);
    }
    std::filesystem::remove_all(folder);
    return 0;
}
