// Robustness suite: the skeleton of shapes whose answer is known, under what real scans do
// to them. Prints a table (one row per shape and condition, one child process each) and a
// summary per condition. Deterministic: the same seeds give the same table.
//
// Shapes: tubes along known curves (their skeleton is the curve; among them thin legs on a
// thick body, two close parallel tubes, three rings of genus 3) and real models from
// Debian's libcgal-demo (known cycles; tips where the anatomy says). Conditions: clean;
// Gaussian noise of 0.5, 1, 2% of the bounding-box diagonal (per coordinate); 1% and 5%
// outliers; half the points in 10% of the surface; virtual scans from 1 and 4 views; five
// scans misaligned by 0.5% and 1% (paper Fig. 9).
//
// Columns: cycles, tips and connected parts found / expected ('!' = wrong); distance of the bones to the
// known centre curve, mean and max, in % of the diagonal; share of bone length inside the
// shape; the tip gap (mean distance from each end of the shape to the nearest skeleton
// tip, % of the diagonal) without and with tip extension; warnings of the quality report;
// time of the whole pipeline. Then the paper's plant and tree scans, which have no known
// answer: the node invariant, and how far the worst node is from every point.
//
// usage: bench_robustness [POINTS]      default 6000 points per clean sample
//        bench_robustness [POINTS] --paper
//                                       the paper's pipeline (no outlier detection,
//                                       refinement or tip extension) instead of the default
//        bench_robustness [POINTS] --no-refine
//                                       the default pipeline without refinement
//        bench_robustness [POINTS] --no-link-limit
//                                       the default pipeline without the stretched-link limit
//        bench_robustness [POINTS] --gap-limit X
//                                       gaps in the data bridged up to X node spacings (0: none)
//        bench_robustness [POINTS] --k N | --denoise N
//                                       contraction's neighbour count, denoising passes
//                                       (0 = the defaults' rules, -1 = automatic denoising)
//        bench_robustness [POINTS] --loop-opening X | --loop-clearance F | --gap-stretch X | --min-hole X
//                                       refinement's loop limits (opening 0: no cut; hole 0: no
//                                       loop is filled)
//        bench_robustness [POINTS] --full-resolution | --contracted-points N
//                                       every point contracted, or at most N (the
//                                       multi-resolution pipeline's subsample; default 20000)
//        bench_robustness [POINTS] --shape TEXT
//                                       only the shapes whose name contains TEXT
//        bench_robustness [POINTS] --outliers [ISOLATION CLUSTER LOCAL]
//                                       outlier detection alone: surface points flagged,
//                                       outliers found, per condition
//        bench_robustness [POINTS] --scans DIR
//                                       the paper's scans (corn_v12108, tobacco_v8098, tree_small,
//                                       as .ply or .off) from DIR instead of tests/data/scans; each
//                                       is measured whole and with a third and two thirds of its
//                                       points, drawn with the seed
//        bench_robustness [POINTS] --check-invariant
//                                       exits with 1 if any node of any case (the suite's and the
//                                       paper's scans) is away from its data (data_support.h)
//        bench_robustness [POINTS] --jobs N
//                                       N cases at a time, each in its own process (1 by
//                                       default); the time column then counts shared cores,
//                                       the rest of the table is the same
//        bench_robustness [POINTS] --seed S
//                                       the samples' seed (11 by default, as every table in
//                                       docs/): another seed tells a rule from a lucky sample
//        bench_robustness --write SHAPE CONDITION FILE [POINTS]
//                                       writes one case's cloud (.xyz or .ply), e.g. for
//                                       the pictures in docs/
#include "robustness_suite.h"
#include "run_in_child.h"

#include <pcskeleton/core/openmp_wait_policy.h>
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/internal/spatial_index.h>
#include <pcskeleton/contraction/outlier_detection.h>


#include <algorithm>
#include <array>
#include <chrono>
#include <deque>
#include <cmath>
#include <random>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <memory>
#include <string>
#include <vector>

using namespace pcskeleton;
using namespace pcskeleton::bench;

namespace {


struct Row {
    int points = 0, cycles = 0, tips = 0, components = 0, warnings = 0;
    int away = 0;  // nodes away from their data (data_support.h): 0 unless a step has a bug
    double meanDistance = -1, maxDistance = -1, inside = -1;  // -1: not measurable
    double gapBefore = -1, gapAfter = -1;
    double seconds = 0;
};

struct BoneSample {
    Point position;
    double length;
};

std::vector<BoneSample> sampleBones(const SkeletonGraph& skeleton, double step) {
    std::vector<BoneSample> samples;
    for (const Edge& e : skeleton.edges) {
        const Point a = skeleton.nodes[e[0]], b = skeleton.nodes[e[1]];
        const int pieces = std::max(1, int(std::ceil((b - a).norm() / step)));
        for (int i = 0; i < pieces; ++i) {
            samples.push_back({a + (b - a) * ((i + 0.5) / pieces), (b - a).norm() / pieces});
        }
    }
    return samples;
}

// Mean distance from each end of the shape to the nearest tip (any node if there is none).
double tipGap(const SkeletonGraph& skeleton, const PointList& ends) {
    const std::vector<int> degree = nodeDegrees(skeleton.nodeCount(), skeleton.edges);
    const bool hasTips = std::count(degree.begin(), degree.end(), 1) > 0;
    double sum = 0.0;
    for (const Point& end : ends) {
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t n = 0; n < skeleton.nodeCount(); ++n) {
            if (!hasTips || degree[n] == 1) nearest = std::min(nearest, (skeleton.nodes[n] - end).norm());
        }
        sum += nearest;
    }
    return sum / ends.size();
}

// `tipGaps`: also run the pipeline with tip extension switched the other way, for the tip
// gaps without and with it.
Row measure(const Subject& subject, const Condition& condition, std::size_t n, std::uint32_t seed,
            const SkeletonParameters& pipeline, bool tipGaps) {
    const PointList cloud = condition.make(subject, n, seed);
    const double diagonal = boundingBox(subject.sample(n, seed)).diagonal().norm();
    const auto start = std::chrono::steady_clock::now();
    const SkeletonResult result = computeCurveSkeleton(cloud, pipeline);
    Row row;
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const SkeletonGraph& skeleton = result.skeleton;
    // The tip gaps without and with tip extension, each from its own run: gap bridging starts
    // from the extended tips, so extending a finished skeleton afterwards is not the pipeline.
    SkeletonGraph otherSkeleton;
    if (tipGaps) {
        SkeletonParameters other = pipeline;
        other.graph.extendTips = !pipeline.graph.extendTips;
        otherSkeleton = computeCurveSkeleton(cloud, other).skeleton;
    }
    const SkeletonGraph& unextended = pipeline.graph.extendTips ? otherSkeleton : skeleton;
    const SkeletonGraph& extended = pipeline.graph.extendTips ? skeleton : otherSkeleton;

    row.points = int(cloud.size());
    const SkeletonTopology topology = analyseTopology(skeleton);
    row.cycles = topology.cycles;
    row.tips = topology.tips;
    row.components = topology.components;
    row.warnings = int(result.quality.warnings().size());
    row.away = int(DataSupport(cloud, result.quality.nodeSpacing).unsupportedNodes(skeleton).size());
    const std::vector<BoneSample> samples = sampleBones(skeleton, diagonal / 400.0);
    double totalLength = 0.0, insideLength = 0.0, distanceSum = 0.0, maxDistance = 0.0;
    for (const BoneSample& s : samples) {
        totalLength += s.length;
        if (subject.inside && subject.inside(s.position)) insideLength += s.length;
        if (subject.centreDistance) {
            const double d = subject.centreDistance(s.position);
            distanceSum += d * s.length;
            maxDistance = std::max(maxDistance, d);
        }
    }
    if (totalLength > 0 && subject.inside) row.inside = 100.0 * insideLength / totalLength;
    if (totalLength > 0 && subject.centreDistance) {
        row.meanDistance = 100.0 * distanceSum / totalLength / diagonal;
        row.maxDistance = 100.0 * maxDistance / diagonal;
    }
    if (tipGaps && !subject.ends.empty() && skeleton.nodeCount() > 0) {
        row.gapBefore = 100.0 * tipGap(unextended, subject.ends) / diagonal;
        row.gapAfter = 100.0 * tipGap(extended, subject.ends) / diagonal;
    }
    return row;
}

std::string found(int got, int expected) {
    if (expected == kUnknown) return std::to_string(got) + "/?";
    return std::to_string(got) + "/" + std::to_string(expected) + (got == expected ? " " : "!");
}

std::string number(double value, const char* format = "%.2f") {
    if (value < 0) return "-";
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

struct Tally {
    int cases = 0, right = 0, nearlyRight = 0, partsRight = 0, gaps = 0, away = 0;
    double gapBefore = 0, gapAfter = 0, meanDistance = 0, inside = 0;
    int distances = 0, insides = 0;
};

}  // namespace

// Writes the cloud of one case; returns the exit status.
int writeCase(const std::vector<Subject>& subjects, const std::string& shape, const std::string& condition,
              const std::string& file, std::size_t n, std::uint32_t seed) {
    for (const Subject& subject : subjects) {
        for (const Condition& c : conditions()) {
            if (subject.name == shape && c.name == condition) {
                writePointCloud(c.make(subject, n, seed), file);
                return 0;
            }
        }
    }
    std::fprintf(stderr, "bench_robustness: no case '%s' / '%s'\n", shape.c_str(), condition.c_str());
    return 2;
}

// Outlier detection alone, per condition: the share of surface points wrongly flagged and,
// where outliers were added (appended after the clean sample), the share of them found.
int outlierDetection(const std::vector<Subject>& subjects, std::size_t n, std::uint32_t seed,
                     const OutlierParameters& parameters) {
    std::printf("Outlier detection, isolation factor %.1f, cluster share %.3f, %zu points per clean sample\n",
                parameters.isolationFactor, parameters.clusterShare, n);
    std::printf("%-16s %22s %22s %8s\n", "condition", "surface points flagged", "outliers found", "time");
    for (const Condition& condition : conditions()) {
        std::size_t surface = 0, wrong = 0, outliers = 0, found = 0, worstShape = 0;
        double seconds = 0, worst = 0;
        for (std::size_t s = 0; s < subjects.size(); ++s) {
            const PointList cloud = condition.make(subjects[s], n, seed);
            const bool added = std::string(condition.name).rfind("outliers", 0) == 0;
            const std::size_t clean = added ? subjects[s].sample(n, seed).size() : cloud.size();
            const auto start = std::chrono::steady_clock::now();
            const std::vector<char> flagged = findOutliers(cloud, parameters);
            seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::size_t wrongHere = 0;
            for (std::size_t i = 0; i < cloud.size(); ++i) {
                if (i < clean) wrongHere += flagged[i];
                else found += flagged[i];
            }
            surface += clean, wrong += wrongHere, outliers += cloud.size() - clean;
            if (double(wrongHere) / clean > worst) worst = double(wrongHere) / clean, worstShape = s;
        }
        std::printf("%-16s %8.3f%% (worst %5.2f%%) %21s %7.2fs   worst: %s\n", condition.name, 100.0 * wrong / surface,
                    100.0 * worst, outliers ? (number(100.0 * found / outliers, "%.1f") + "%").c_str() : "-",
                    seconds / subjects.size(), worst > 0 ? subjects[worstShape].name.c_str() : "-");
        std::fflush(stdout);
    }
    return 0;
}

// The indices 0..n-1 shuffled with `seed` (Fisher-Yates on the generator's own output, the
// same on every platform); a prefix of it is a random sample, and a shorter prefix a
// sample of the longer one.
std::vector<std::size_t> shuffledOrder(std::size_t n, std::uint32_t seed) {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::mt19937 random(seed);
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[random() % i]);
    return order;
}

// The paper's scans without ground truth: each file found in `folder` as NAME.ply or NAME.off,
// whole and with a third and two thirds of its points (drawn with `seed`): a scan of the same
// plant may come denser or sparser, and a rule that keeps the skeleton on the leaves should
// not hold at one density only. Returns the nodes away from their data, in all.
int measurePaperScans(const std::string& folder, const SkeletonParameters& pipeline, std::uint32_t seed) {
    std::printf("\nThe paper's scans, whole and with a third or two thirds of their points (no known answer;\n"
                "worst: the node farthest from every point of the whole scan, in %% of its diagonal)\n"
                "%-20s %7s %6s %6s %5s %8s %10s %5s %6s\n",
                "scan", "points", "cycles", "tips", "parts", "worst", "over 2.5%", "away", "time");
    int away = 0;
    for (const char* name : {"corn_v12108", "tobacco_v8098", "tree_small"}) {
        std::filesystem::path file;
        for (const char* extension : {".ply", ".off"}) {
            if (std::filesystem::exists(std::filesystem::path(folder) / (std::string(name) + extension))) {
                file = std::filesystem::path(folder) / (std::string(name) + extension);
                break;
            }
        }
        if (file.empty()) {
            std::printf("%-20s (not in %s)\n", name, folder.c_str());
            continue;
        }
        const PointList whole = readPointCloud(file.string());
        const PointIndex index(whole);
        const double diagonal = boundingBox(whole).diagonal().norm();
        const std::vector<std::size_t> order = shuffledOrder(whole.size(), seed);
        for (std::size_t thirds : {3, 1, 2}) {
            PointList cloud;
            if (thirds == 3) {
                cloud = whole;  // in the file's order: the skeleton depends on the points' order
            } else {
                for (std::size_t k = 0; k < whole.size() * thirds / 3; ++k) cloud.push_back(whole[order[k]]);
            }
            const auto start = std::chrono::steady_clock::now();
            const SkeletonResult result = computeCurveSkeleton(cloud, pipeline);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const int caseAway =
                int(DataSupport(cloud, result.quality.nodeSpacing).unsupportedNodes(result.skeleton).size());
            double worst = 0.0;
            int over = 0;
            for (const Point& node : result.skeleton.nodes) {
                std::vector<int> nearest;
                index.nearest(node, 1, nearest);
                const double share = (whole[nearest.at(0)] - node).norm() / diagonal;
                worst = std::max(worst, share);
                over += share > 0.025;
            }
            const SkeletonTopology t = analyseTopology(result.skeleton);
            const std::string label = std::string(name) + (thirds == 3 ? "" : thirds == 1 ? " 1/3" : " 2/3");
            std::printf("%-20s %7zu %6d %6d %5d %7.2f%% %10d %5d %5.1fs\n", label.c_str(), cloud.size(), t.cycles,
                        t.tips, t.components, 100.0 * worst, over, caseAway, seconds);
            away += caseAway;
        }
    }
    return away;
}

const char* const kUsage =
    "usage: bench_robustness [POINTS] [--paper] [--no-refine] [--no-recentre] [--extend-tips] [--no-link-limit]\n"
    "                        [--gap-limit X] [--loop-opening X] [--loop-clearance F] [--full-resolution]\n"
    "                        [--gap-stretch X] [--min-hole X] [--k N] [--denoise N]\n"
    "                        [--contracted-points N] [--shape TEXT] [--scans DIR] [--check-invariant]\n"
    "                        [--seed S] [--medial-pull W] [--jobs N]\n"
    "       bench_robustness --outliers [POINTS [ISOLATION [CLUSTER [LOCAL]]]]\n"
    "       bench_robustness --write SHAPE CONDITION FILE [POINTS]\n"
    "The table of every shape under every scan defect (the default), the outlier detector's scores, or one\n"
    "case written as a PLY file. POINTS: points per clean sample (6000).\n";

int main(int argc, char** argv) {
    pcskeleton::restartWithPassiveOpenMpWaits(argv);
    std::vector<std::string> args(argv + 1, argv + argc);
    // Switches stand alone; options with a value take the next argument; --write the next three.
    const std::set<std::string> switches{"--paper",         "--no-refine",        "--no-recentre", "--extend-tips",
                                         "--no-link-limit", "--full-resolution", "--outliers",    "--check-invariant"};
    const std::set<std::string> optionsWithValue{"--contracted-points", "--shape", "--gap-limit", "--loop-opening",
                                                 "--loop-clearance", "--k",                 "--denoise",
                                                 "--gap-stretch",      "--scans",         "--min-hole",
                                                 "--seed",             "--medial-pull",   "--jobs"};
    for (const std::string& arg : args) {
        if (arg == "--help" || arg == "-h") {
            std::printf("%s", kUsage);
            return 0;
        }
        if (arg.rfind("--", 0) == 0 && arg != "--write" && !switches.count(arg) && !optionsWithValue.count(arg)) {
            std::fprintf(stderr, "bench_robustness: unknown option %s\n%s", arg.c_str(), kUsage);
            return 2;
        }
    }
    // One pass; what is left must be numbers (POINTS, then --outliers' factors). A word where a
    // number belongs is refused rather than read as 0.
    const std::set<std::string> textValues{"--shape", "--scans"};
    std::set<std::string> given;
    std::map<std::string, std::string> values;
    std::vector<std::string> written;  // SHAPE CONDITION FILE
    std::vector<double> numbers;
    const auto refuse = [](const std::string& problem) {
        std::fprintf(stderr, "bench_robustness: %s\n%s", problem.c_str(), kUsage);
        return 2;
    };
    const auto parseNumber = [](const std::string& text, double& value) {
        char* end = nullptr;
        value = std::strtod(text.c_str(), &end);
        return !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
    };
    for (std::size_t a = 0; a < args.size(); ++a) {
        const std::string& arg = args[a];
        if (arg == "--write") {
            if (a + 3 >= args.size()) return refuse("--write needs SHAPE CONDITION FILE");
            written.assign(args.begin() + long(a) + 1, args.begin() + long(a) + 4);
            a += 3;
        } else if (optionsWithValue.count(arg)) {
            if (a + 1 >= args.size()) return refuse(arg + " needs a value");
            double number = 0;
            if (!textValues.count(arg) && !parseNumber(args[a + 1], number)) {
                return refuse(arg + " needs a number, not '" + args[a + 1] + "'");
            }
            values[arg] = args[++a];
        } else if (switches.count(arg)) {
            given.insert(arg);
        } else {
            double number = 0;
            if (!parseNumber(arg, number)) return refuse("'" + arg + "' is not a number");
            numbers.push_back(number);
        }
    }
    const bool write = !written.empty();
    const bool outliers = given.count("--outliers") > 0;
    const bool paper = given.count("--paper") > 0;
    std::size_t n = 6000;
    // Fewer points than this leave a shape's thinnest parts without a sample.
    constexpr double kFewestPoints = 100;
    if (!numbers.empty()) {
        if (!(numbers[0] >= kFewestPoints && numbers[0] <= 1e9)) return refuse("POINTS must be between 100 and 1e9");
        n = std::size_t(numbers[0]);
    }
    SkeletonParameters pipeline = paper ? SkeletonParameters::paper() : SkeletonParameters{};
    if (given.count("--no-refine")) pipeline.graph.refine = false;
    if (given.count("--no-recentre")) pipeline.graph.recentre = false;
    if (given.count("--extend-tips")) pipeline.graph.extendTips = true;
    if (given.count("--no-link-limit")) pipeline.graph.linkLimit = 0;
    const auto numberAfter = [&](const char* option, double& value) {
        const auto found = values.find(option);
        if (found != values.end()) value = std::strtod(found->second.c_str(), nullptr);
    };
    numberAfter("--gap-limit", pipeline.graph.gapLimit);
    numberAfter("--loop-opening", pipeline.graph.refinementLimits.minOpening);
    numberAfter("--loop-clearance", pipeline.graph.refinementLimits.minClearance);
    numberAfter("--gap-stretch", pipeline.graph.refinementLimits.gapStretch);
    numberAfter("--min-hole", pipeline.graph.refinementLimits.minHole);
    numberAfter("--medial-pull", pipeline.contraction.medialPull);
    double seedValue = 11;
    numberAfter("--seed", seedValue);
    const auto seed = std::uint32_t(seedValue);
    double jobsValue = 1;
    numberAfter("--jobs", jobsValue);
    if (!(jobsValue >= 1 && jobsValue <= 64 && jobsValue == std::floor(jobsValue))) {
        return refuse("--jobs needs a whole number from 1 to 64");
    }
    const auto jobs = std::size_t(jobsValue);
    double neighbours = pipeline.contraction.neighbourCount, denoising = pipeline.contraction.denoisingPasses;
    numberAfter("--k", neighbours);
    numberAfter("--denoise", denoising);
    pipeline.contraction.neighbourCount = int(neighbours);
    pipeline.contraction.denoisingPasses = int(denoising);
    if (given.count("--full-resolution")) pipeline.resolution.maxContractedPoints = 0;
    // --shape TEXT: only the shapes whose name contains TEXT (e.g. the slow ones at 1M points).
    const std::string onlyShape = values.count("--shape") ? values["--shape"] : "";
    double contractedPoints = double(pipeline.resolution.maxContractedPoints);
    numberAfter("--contracted-points", contractedPoints);
    pipeline.resolution.maxContractedPoints = std::size_t(contractedPoints);
    const std::string scans = values.count("--scans") ? values["--scans"] : PCSKELETON_SCANS_DIR;
    const bool checkInvariant = given.count("--check-invariant") > 0;
    const std::vector<Subject> subjects = robustnessSubjects();

    if (write) return writeCase(subjects, written[0], written[1], written[2], n, seed);
    if (outliers) {
        OutlierParameters parameters;
        if (numbers.size() > 1) parameters.isolationFactor = numbers[1];
        if (numbers.size() > 2) parameters.clusterShare = numbers[2];
        if (numbers.size() > 3) parameters.localFactor = numbers[3];
        return outlierDetection(subjects, n, seed, parameters);
    }
    std::printf("Skeleton robustness, %s pipeline, %zu points per clean sample, seed %u, %ld cores. Distances and gaps "
                "in %% of the bounding-box diagonal.\n",
                paper ? "the paper's" : "the default", n, seed, sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("%-24s %-16s %6s %6s %6s %5s %6s %6s %7s %13s %4s %4s %6s\n", "shape", "condition", "points",
                "cycles", "tips", "parts", "mean d", "max d", "inside", "tip gap", "away", "warn", "time");
    // Per condition, the tuning half ([0]) and the held-out half ([1]).
    std::map<std::string, std::array<Tally, 2>> byCondition;
    int away = 0;
    const std::vector<Condition> scanConditions = conditions();
    std::vector<std::pair<const Subject*, const Condition*>> cases;
    for (const Subject& subject : subjects) {
        if (subject.name.find(onlyShape) == std::string::npos) continue;
        for (const Condition& condition : scanConditions) cases.emplace_back(&subject, &condition);
    }
    // Up to `jobs` cases run at a time; their rows are printed in the suite's order.
    std::deque<ChildCase> running;
    std::size_t started = 0;
    for (std::size_t next = 0; next < cases.size(); ++next) {
        for (; started < cases.size() && running.size() < jobs; ++started) {
            const auto [subject, condition] = cases[started];
            running.push_back(startInChild<Row>(
                [&, subject = subject, condition = condition] {
                    return measure(*subject, *condition, n, seed, pipeline, !checkInvariant);
                }));
        }
        const Subject& subject = *cases[next].first;
        const Condition& condition = *cases[next].second;
        Row row;
        double peak = 0;
        const bool finished = finishInChild(running.front(), row, peak);
        running.pop_front();
        if (!finished) {
            std::printf("%-24s %-16s failed\n", subject.name.c_str(), condition.name);
            continue;
        }
        const std::string gap = row.gapBefore < 0 ? "-" : number(row.gapBefore) + "->" + number(row.gapAfter);
        std::printf("%-24s %-16s %6d %6s %6s %5s %6s %6s %6s%% %13s %4d %4d %5.1fs\n", subject.name.c_str(),
                    condition.name, row.points, found(row.cycles, subject.cycles).c_str(),
                    found(row.tips, subject.tips).c_str(), found(row.components, subject.components).c_str(),
                    number(row.meanDistance).c_str(), number(row.maxDistance).c_str(),
                    number(row.inside, "%.0f").c_str(), gap.c_str(), row.away, row.warnings, row.seconds);
        std::fflush(stdout);
        Tally& t = byCondition[condition.name][subject.heldOut ? 1 : 0];
        t.away += row.away;
        away += row.away;
        ++t.cases;
        const bool cyclesAndParts = row.cycles == subject.cycles && row.components == subject.components;
        t.partsRight += row.components == subject.components;
        t.right += cyclesAndParts && (subject.tips == kUnknown || row.tips == subject.tips);
        t.nearlyRight += cyclesAndParts && (subject.tips == kUnknown || std::abs(row.tips - subject.tips) <= 1);
        if (row.gapBefore >= 0) t.gapBefore += row.gapBefore, t.gapAfter += row.gapAfter, ++t.gaps;
        if (row.meanDistance >= 0) t.meanDistance += row.meanDistance, ++t.distances;
        if (row.inside >= 0) t.inside += row.inside, ++t.insides;
    }
    std::printf("\nSummary per condition (means over the shapes that have the measure; right topology: cycles,\n"
                "parts and tips as the shape's; tips +-1: the same with one tip more or fewer allowed; parts: the\n"
                "skeleton in as many pieces as the shape; away: nodes away from their data, in all). Defaults are\n"
                "chosen on the tuning half; the held-out half tells whether they generalise.\n");
    for (int half : {0, 1}) {
        std::printf("%s half\n", half == 0 ? "Tuning" : "Held-out");
        std::printf("%-16s %13s %9s %9s %8s %8s %15s %5s\n", "condition", "right topology", "tips +-1", "parts",
                    "mean d", "inside", "tip gap", "away");
        for (const Condition& condition : conditions()) {
            const Tally& t = byCondition[condition.name][half];
            if (t.cases == 0) continue;
            std::printf("%-16s %9d/%-3d %5d/%-3d %5d/%-3d %8s %7s%% %15s %5d\n", condition.name, t.right, t.cases,
                        t.nearlyRight, t.cases, t.partsRight, t.cases,
                        number(t.distances ? t.meanDistance / t.distances : -1).c_str(),
                        number(t.insides ? t.inside / t.insides : -1, "%.0f").c_str(),
                        t.gaps ? (number(t.gapBefore / t.gaps) + "->" + number(t.gapAfter / t.gaps)).c_str() : "-",
                        t.away);
        }
    }
    away += measurePaperScans(scans, pipeline, seed);
    if (checkInvariant && away > 0) {
        std::printf("\n%d nodes away from their data: a finishing step broke the invariant.\n", away);
        return 1;
    }
    return 0;
}
