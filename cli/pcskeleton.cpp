// pcskeleton: point cloud in, curve skeleton out, from the command line. Built from
// vcg_ext alone (no Qt, no X server) for pipelines, benchmarks and headless machines.
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/core/openmp_wait_policy.h>
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>
#include <pcskeleton/io/input_file.h>
#include <pcskeleton/io/mesh_io.h>
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/io/skeleton_io.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <unistd.h>
#include <utility>

using namespace pcskeleton;

namespace {

struct Options {
    std::string input, output, contracted, correspondence, report;
    std::string skeleton;  // a given (edited) skeleton to reconstruct from, instead of computing one
    std::string surface;   // where to write the reconstructed surface
    SkeletonParameters parameters;
    ReconstructionParameters reconstruction;
    bool quiet = false;
    bool force = false;  // replace existing output files
};

class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The library's advice in this tool's terms: each parameter by its option.
std::string optionOf(Parameter parameter) {
    switch (parameter) {
        case Parameter::NeighbourCount: return "--k";
        case Parameter::InitialContractionWeight: return "--wl";
        case Parameter::InitialAttractionWeight: return "--wh";
        case Parameter::ContractionScale: return "--sl";
        case Parameter::MaxContractionWeight: return "--max-wl";
        case Parameter::MaxAttractionWeight: return "--max-wh";
        case Parameter::LaplacianRowLimit: return "--row-limit";
        case Parameter::MaxIterations: return "--iterations";
        case Parameter::TerminationThreshold: return "--threshold";
        case Parameter::NodeSpacing: return "--radius";
        case Parameter::Refinement: return "refinement (--no-refine turns it off)";
        case Parameter::OutlierDetection: return "outlier detection (--keep-outliers turns it off)";
        case Parameter::OutlierIsolation: return "--outlier-isolation";
        case Parameter::OutlierLocalFactor: return "--outlier-local";
        case Parameter::OutlierClusterShare: return "--outlier-cluster";
        case Parameter::DenoisingPasses: return "--denoise";
        case Parameter::LinkLimit: return "--link-limit";
        case Parameter::GapLimit: return "--gap-limit";
        case Parameter::LoopOpening: return "--loop-opening";
        case Parameter::LoopClearance: return "--loop-clearance";
        case Parameter::GapStretch: return "--gap-stretch";
        case Parameter::ContractedPoints: return "--contracted-points (without --full-resolution)";
        case Parameter::Resolution: return "--resolution";
        case Parameter::SmoothWeight: return "--smooth-weight";
        case Parameter::SurfaceWeight: return "--surface-weight";
        case Parameter::SkeletonWeight: return "--skeleton-weight";
        case Parameter::OutsideWeight: return "--outside-weight";
        case Parameter::OutsideDistance: return "--outside-radii";
        case Parameter::SkeletonTopology: return "the topology guarantee (--data-topology turns it off)";
        default: return libraryTerms().parameter(parameter);
    }
}

std::string stepInThisTool(Step step) {
    switch (step) {
        case Step::RemoveOutliers: return "remove outliers from the input first";
        case Step::RemoveNonFinitePoints: return "remove them from the input first";
        case Step::DeleteNodes: return "delete them by hand (MeshLab's Edit Skeleton tool)";
        case Step::MergeNodes: return "merge their nodes by hand (MeshLab's Edit Skeleton tool)";
        case Step::SetNodeRadii: return "give the skeleton radii (a .ply skeleton from -o has them)";
        case Step::ComputeSkeleton: return "compute the skeleton of these points (leave out --skeleton)";
        default: return libraryTerms().step(step);
    }
}

const Terms& commandLineTerms() {
    static const Terms terms{optionOf, stepInThisTool};
    return terms;
}

void printHelp() {
    const ContractionParameters c;
    const ThinningParameters t;
    const OutlierParameters o;
    const ReconstructionParameters r;
    const ResolutionParameters m;
    std::printf(
        "Usage: pcskeleton INPUT -o OUTPUT [options]             the skeleton\n"
        "       pcskeleton INPUT -o OUTPUT --surface SURFACE [...]  and the surface it gives\n"
        "       pcskeleton INPUT --skeleton SKELETON --surface SURFACE\n"
        "                                          the surface from a given (edited) skeleton\n"
        "\n"
        "Extracts the curve skeleton of a point cloud by Laplacian-based contraction\n"
        "(Cao et al., SMI 2010): contraction, thinning, embedding. The paper's parameters\n"
        "are the defaults; the steps it does not have (outlier detection, denoising,\n"
        "the stretched-link limit, re-centring, refinement, tip extension) are on by\n"
        "default because they measured better on imperfect scans, and --paper turns them\n"
        "all off. Every length is relative to the cloud's size: the same command works in\n"
        "millimetres or kilometres.\n"
        "\n"
        "INPUT      point set: .ply (ascii or binary, either byte order), .off, .obj\n"
        "           (faces are ignored, so meshes and polygon soups work), .xyz/.txt/.pts\n"
        "           (x y z per line); never modified\n"
        "-o FILE    the skeleton: .ply (vertices with radius, element edge), .obj (v and\n"
        "           l lines) or .cg (Starlab curve-skeleton format; no radius)\n"
        "\n"
        "Surface (paper Sec. V): a closed surface through the points whose inside and\n"
        "topology follow the skeleton; the scan's holes are closed where the skeleton says.\n"
        "  --surface FILE        write it to FILE: .ply (binary), .off or .obj\n"
        "  --skeleton FILE       reconstruct from this skeleton (.ply with radii, as -o\n"
        "                        writes it; .obj/.cg have none) instead of computing one\n"
        "  --resolution N        grid cells on the longest side [%d]\n"
        "  --smooth-weight X     w1, smoothness of the field [%g]\n"
        "  --surface-weight X    w2, the surface passes through the points [%g]\n"
        "  --skeleton-weight X   w3, the field is -radius on the skeleton [%g]\n"
        "  --outside-weight X    w4, the field is positive far from the skeleton [%g]\n"
        "  --outside-radii K     \"far\" is more than K node radii from the skeleton [%g]\n"
        "  --data-topology       the paper's plain fit: the surface may have handles and\n"
        "                        parts the skeleton has not (by default they are cut away\n"
        "                        and the surface has exactly the skeleton's topology)\n"
        "  --uniform-point-weights  every point weighs w2 (the paper); by default points\n"
        "                        whose neighbours scatter across the surface by more than\n"
        "                        a grid cell (noise) weigh less, so noise makes no bumps\n"
        "  --level-set           the field's zero level set as it is (the paper); by\n"
        "                        default, where there are points, the surface's vertices\n"
        "                        move (at most a cell) onto a local fit of the points\n"
        "\n"
        "After the run a quality report goes to stderr: cycles, tips, junctions, parts,\n"
        "whether contraction converged, and warnings (points that did not contract, parts\n"
        "that gave no bone, nodes outside the shape, short spurs, loops without a hole),\n"
        "each naming the option that usually fixes it.\n"
        "\n"
        "Options (default in brackets):\n"
        "  --contracted FILE     also write the contracted points (.ply or .xyz)\n"
        "  --correspondence FILE also write, for each input point, its node's index\n"
        "                        (one per line, 0-based, in the input's order; -1 for a\n"
        "                        point with no node, e.g. an outlier)\n"
        "  --k N                 neighbours whose tangent-plane Delaunay gives each point's\n"
        "                        1-ring [%d = 1.2%% of the points, between 8 and 30]. Raise\n"
        "                        for noisy scans; lower if close parts get connected.\n"
        "  --wl X                initial contraction weight W_L0 [%g = 1/(5 x mean 1-ring\n"
        "                        size)]. Too high pulls thin parts into thick ones; too low\n"
        "                        leaves tips sticking out.\n"
        "  --wh X                initial attraction weight W_H0 [%g]; opposes --wl\n"
        "  --sl X                W_L grows by this factor per iteration [%g]; use 2 when thin\n"
        "                        parts join thick ones (paper Fig. 10)\n"
        "  --max-wl X            cap on W_L [%g]\n"
        "  --max-wh X            cap on each point's W_H [%g]\n"
        "  --row-limit X         cap on a Laplacian row's weight sum [%g]\n"
        "  --iterations N        contraction iterations at most [%d]\n"
        "  --threshold X         stop when the 1-ring size shrinks by less than this\n"
        "                        fraction in an iteration [%g]\n"
        "  --radius R            thinning ball radius as a fraction of the bounding-box\n"
        "                        diagonal [%g]. Larger merges close parts and small loops;\n"
        "                        smaller keeps more detail and more noise.\n"
        "  --link-limit X        1-ring neighbours whose contracted points ended more than X\n"
        "                        radii (--radius) apart were pulled to different bones\n"
        "                        (parts that touch, noise across a gap): they connect their\n"
        "                        nodes only where nothing else does [%g]. Lower it if close\n"
        "                        parts get false loops; 0 = every neighbour connects (paper)\n"
        "  --gap-limit X         where a limb points at another piece of the skeleton at most\n"
        "                        X radii (--radius) ahead (a gap in the data: an occluded or\n"
        "                        missing stretch), a bone joins them [%g]. Pieces side by\n"
        "                        side are never joined; 0 = no bridge (paper)\n"
        "  --no-extend-tips      keep the tips where contraction left them (the paper's\n"
        "                        skeleton); by default each limb is extended to the end of\n"
        "                        its tip's points, since contraction shortens limbs\n"
        "  --no-refine           keep short spurs and loops smaller than their tube, and\n"
        "                        junctions closer than the node spacing; by default they are\n"
        "                        removed or merged, loops narrower than their tube where\n"
        "                        parts touch are opened, and bridges of a handful of points\n"
        "                        or a single bone across a gap, between parts that pass\n"
        "                        close, are cut (noise and misaligned scans leave them).\n"
        "                        --refine turns it on again after --paper.\n"
        "  --loop-opening X      refinement opens a loop whose hole is narrower than X tube\n"
        "                        radii [%g] at its bone longest for its radii, if that bone\n"
        "  --loop-clearance F    passes closer than F of its radius to a point [%g]: parts\n"
        "                        that touch or that noise joined. Lower either if a real\n"
        "                        narrow hole is lost; --loop-opening 0 opens none\n"
        "  --gap-stretch X       refinement cuts a bone joining two strands that pass close\n"
        "                        straight across the gap between them: on a loop, between\n"
        "                        junctions the strands run through, longer than X times the\n"
        "                        radii at its two ends together [%g] (their tubes do not\n"
        "                        meet along it). Raise it if a real bone is cut; 0 cuts none\n"
        "  --no-recentre         leave every node at the centre of its points; by default a\n"
        "                        node whose points cover one side of its bone only (one-view\n"
        "                        scans, holes) moves to the centre of the circle through them\n"
        "  --keep-outliers       contract every point; by default points that do not belong\n"
        "                        to the sampled surface (isolated points, small sparse\n"
        "                        clusters) are set aside and get no node (-1 in\n"
        "                        --correspondence)\n"
        "  --outlier-isolation F a point whose 8th nearest neighbour is farther than F\n"
        "                        typical spacings is an outlier [%g]; raise it if sparse\n"
        "                        parts of the shape are taken for outliers\n"
        "  --outlier-local G     a point whose 8th nearest neighbour is farther than G times\n"
        "                        that of its neighbours (their upper quartile) is an outlier\n"
        "                        [%g]; lower finds outliers closer to the surface\n"
        "  --outlier-cluster S   groups of points holding less than this share of the cloud\n"
        "                        are outlier clusters [%g]; 0 keeps every group\n"
        "  --denoise N           contract a copy of the points denoised by N passes of\n"
        "                        projection onto the plane of each point's k nearest\n"
        "                        neighbours; the nodes still sit among the points as given.\n"
        "                        [%d] = automatic: %d passes if the cloud is noisy (its\n"
        "                        surface noise, in the report, above %g), none if clean;\n"
        "                        0 never (the paper); 1-%d passes always\n"
        "  --contracted-points N a cloud of more points is contracted through a well-spread\n"
        "                        subsample of at most N (one per cube of a grid); every\n"
        "                        point still gets its node and the radii come from all\n"
        "                        points [%zu]. Raise it for fine detail in huge scans.\n"
        "                        Up to 20000 contracted points the skeleton is the same\n"
        "                        on every CPU; above, a faster solver's result may differ\n"
        "                        in its last digits from one CPU to another\n"
        "  --full-resolution     contract every point (the paper; about 2.7 KB of memory\n"
        "                        per point, minutes at 1M points)\n"
        "  --memory-limit GB     refuse, before any work, a cloud whose computation would\n"
        "                        need more [80%% of the machine's memory]\n"
        "  --paper               the paper's pipeline exactly: the same as --keep-outliers\n"
        "                        --denoise 0 --no-recentre --no-refine --no-extend-tips\n"
        "                        --link-limit 0 --gap-limit 0 --full-resolution (and\n"
        "                        --data-topology --uniform-point-weights --level-set)\n"
        "  --report FILE         also write the quality report to FILE\n"
        "  --force               replace output files that exist already (never the input)\n"
        "  --quiet               no progress and no summary on stderr\n"
        "  -h, --help            this text\n"
        "\n"
        "Files: the input is never modified. An output that exists already is refused\n"
        "unless --force is given; an output naming the input is always refused. Each\n"
        "output appears only once complete (written aside, then renamed).\n"
        "\n"
        "Exit status: 0 on success, 1 when the input cannot be processed (the reason is\n"
        "printed on one line), 2 on a command-line error.\n",
        r.resolution, r.smoothWeight, r.surfaceWeight, r.skeletonWeight, r.outsideWeight, r.outsideRadii,
        c.neighbourCount, c.initialContractionWeight, c.initialAttractionWeight, c.contractionScale,
        c.maxContractionWeight, c.maxAttractionWeight, c.laplacianRowLimit, c.maxIterations, c.terminationThreshold,
        t.sampleRadius, t.linkLimit, t.gapLimit, t.narrowLoops.minOpening, t.narrowLoops.minClearance, t.narrowLoops.gapStretch, o.isolationFactor, o.localFactor, o.clusterShare, c.denoisingPasses,
        kPassesForNoisySurface, kNoisySurface, kMaximumDenoisingPasses, m.maxContractedPoints);
}

double parseNumber(const std::string& option, const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') throw UsageError(option + " expects a number, got '" + text + "'");
    return value;
}

int parseInteger(const std::string& option, const std::string& text) {
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0') throw UsageError(option + " expects an integer, got '" + text + "'");
    // A value that does not fit would otherwise wrap around (2^31 became a negative count).
    if (errno == ERANGE || value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
        throw UsageError(option + " " + text + " is out of range (at most " +
                         std::to_string(std::numeric_limits<int>::max()) + ")");
    }
    return static_cast<int>(value);
}

bool samePath(const std::string& a, const std::string& b) {
    if (sameFile(a, b)) return true;
    std::error_code first, second;  // a name that cannot be resolved (a symlink loop) names no other file
    const std::filesystem::path x = std::filesystem::weakly_canonical(a, first);
    const std::filesystem::path y = std::filesystem::weakly_canonical(b, second);
    return !first && !second && x == y;
}

// Before any work: no output may be the input or another output, an existing output is
// replaced only with --force, and each output's folder must exist.
void checkOutputs(const Options& options) {
    const std::vector<std::pair<std::string, std::string>> outputs = {{"-o", options.output},
                                                                      {"--contracted", options.contracted},
                                                                      {"--correspondence", options.correspondence},
                                                                      {"--report", options.report},
                                                                      {"--surface", options.surface}};
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& [option, path] = outputs[i];
        if (path.empty()) continue;
        for (const std::string& input : {options.input, options.skeleton}) {
            if (!input.empty() && samePath(path, input)) {
                throw UsageError(option + " '" + path +
                                 "' is an input file; choose another name (inputs are never overwritten)");
            }
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (!outputs[j].second.empty() && samePath(path, outputs[j].second)) {
                throw UsageError(outputs[j].first + " and " + option + " name the same file '" + path + "'");
            }
        }
        try {
            checkWritable(path);
        } catch (const InvalidInput& e) {
            throw UsageError(option + ": " + e.problem().description);
        }
        if (fileExists(path) && !options.force) {
            throw UsageError(option + " '" + path + "' exists already; choose another name or add --force to replace it");
        }
    }
}

// Returns false when --help was given.
bool parseArguments(int argc, char** argv, Options& options) {
    ContractionParameters& c = options.parameters.contraction;
    ReconstructionParameters& r = options.reconstruction;
    const std::map<std::string, std::function<void(const std::string&)>> withValue = {
        {"-o", [&](const std::string& v) { options.output = v; }},
        {"--output", [&](const std::string& v) { options.output = v; }},
        {"--contracted", [&](const std::string& v) { options.contracted = v; }},
        {"--correspondence", [&](const std::string& v) { options.correspondence = v; }},
        {"--report", [&](const std::string& v) { options.report = v; }},
        {"--skeleton", [&](const std::string& v) { options.skeleton = v; }},
        {"--surface", [&](const std::string& v) { options.surface = v; }},
        {"--resolution", [&](const std::string& v) { r.resolution = parseInteger("--resolution", v); }},
        {"--smooth-weight", [&](const std::string& v) { r.smoothWeight = parseNumber("--smooth-weight", v); }},
        {"--surface-weight", [&](const std::string& v) { r.surfaceWeight = parseNumber("--surface-weight", v); }},
        {"--skeleton-weight", [&](const std::string& v) { r.skeletonWeight = parseNumber("--skeleton-weight", v); }},
        {"--outside-weight", [&](const std::string& v) { r.outsideWeight = parseNumber("--outside-weight", v); }},
        {"--outside-radii", [&](const std::string& v) { r.outsideRadii = parseNumber("--outside-radii", v); }},
        {"--k", [&](const std::string& v) { c.neighbourCount = parseInteger("--k", v); }},
        {"--wl", [&](const std::string& v) { c.initialContractionWeight = parseNumber("--wl", v); }},
        {"--wh", [&](const std::string& v) { c.initialAttractionWeight = parseNumber("--wh", v); }},
        {"--sl", [&](const std::string& v) { c.contractionScale = parseNumber("--sl", v); }},
        {"--max-wl", [&](const std::string& v) { c.maxContractionWeight = parseNumber("--max-wl", v); }},
        {"--max-wh", [&](const std::string& v) { c.maxAttractionWeight = parseNumber("--max-wh", v); }},
        {"--row-limit", [&](const std::string& v) { c.laplacianRowLimit = parseNumber("--row-limit", v); }},
        {"--iterations", [&](const std::string& v) { c.maxIterations = parseInteger("--iterations", v); }},
        {"--threshold", [&](const std::string& v) { c.terminationThreshold = parseNumber("--threshold", v); }},
        {"--radius", [&](const std::string& v) { options.parameters.thinning.sampleRadius = parseNumber("--radius", v); }},
        {"--link-limit", [&](const std::string& v) { options.parameters.thinning.linkLimit = parseNumber("--link-limit", v); }},
        {"--gap-limit", [&](const std::string& v) { options.parameters.thinning.gapLimit = parseNumber("--gap-limit", v); }},
        {"--loop-opening", [&](const std::string& v) { options.parameters.thinning.narrowLoops.minOpening = parseNumber("--loop-opening", v); }},
        {"--loop-clearance", [&](const std::string& v) { options.parameters.thinning.narrowLoops.minClearance = parseNumber("--loop-clearance", v); }},
        {"--gap-stretch", [&](const std::string& v) { options.parameters.thinning.narrowLoops.gapStretch = parseNumber("--gap-stretch", v); }},
        {"--outlier-isolation", [&](const std::string& v) { c.outliers.isolationFactor = parseNumber("--outlier-isolation", v); }},
        {"--outlier-local", [&](const std::string& v) { c.outliers.localFactor = parseNumber("--outlier-local", v); }},
        {"--outlier-cluster", [&](const std::string& v) { c.outliers.clusterShare = parseNumber("--outlier-cluster", v); }},
        {"--denoise", [&](const std::string& v) { c.denoisingPasses = parseInteger("--denoise", v); }},
        {"--contracted-points", [&](const std::string& v) {
             const int count = parseInteger("--contracted-points", v);
             if (count < 1) throw UsageError("--contracted-points must be at least 1 (--full-resolution contracts every point)");
             options.parameters.resolution.maxContractedPoints = std::size_t(count);
         }},
        {"--memory-limit", [&](const std::string& v) {
             const double gigabytes = parseNumber("--memory-limit", v);
             if (!(gigabytes > 0) || !std::isfinite(gigabytes)) throw UsageError("--memory-limit must be a positive number of GB");
             options.parameters.resolution.memoryLimit = gigabytes * 1e9;
         }},
    };
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") return false;
        if (arg == "--quiet") {
            options.quiet = true;
        } else if (arg == "--force") {
            options.force = true;
        } else if (arg == "--no-extend-tips") {
            options.parameters.thinning.extendTips = false;
        } else if (arg == "--refine" || arg == "--no-refine") {
            options.parameters.thinning.refine = arg == "--refine";
        } else if (arg == "--no-recentre") {
            options.parameters.thinning.recentre = false;
        } else if (arg == "--full-resolution") {
            options.parameters.resolution.maxContractedPoints = 0;
        } else if (arg == "--keep-outliers") {
            c.outliers.detect = false;
        } else if (arg == "--data-topology") {
            options.reconstruction.keepSkeletonTopology = false;
        } else if (arg == "--uniform-point-weights") {
            options.reconstruction.adaptToNoise = false;
        } else if (arg == "--level-set") {
            options.reconstruction.fitVerticesToPoints = false;
        } else if (arg == "--paper") {
            options.parameters.keepToThePaper();
            options.reconstruction.keepToThePaper();
        } else if (auto option = withValue.find(arg); option != withValue.end()) {
            if (i + 1 >= argc) throw UsageError(arg + " needs a value");
            option->second(argv[++i]);
        } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
            throw UsageError("unknown option " + arg);
        } else if (options.input.empty()) {
            options.input = arg;
        } else {
            throw UsageError("more than one input file ('" + options.input + "' and '" + arg + "')");
        }
    }
    if (options.input.empty()) throw UsageError("no input file");
    if (!options.skeleton.empty()) {
        if (options.surface.empty()) throw UsageError("--skeleton is for reconstruction: add --surface FILE");
        if (!options.output.empty() || !options.contracted.empty() || !options.correspondence.empty()) {
            throw UsageError("with --skeleton no skeleton is computed: leave out -o, --contracted and --correspondence");
        }
    } else {
        if (options.output.empty()) throw UsageError("no output file (-o FILE)");
        if (!isSkeletonFileName(options.output)) throw UsageError("the output must end in .ply, .obj or .cg");
    }
    if (!options.surface.empty() && !isMeshFileName(options.surface)) {
        throw UsageError("the surface must end in .ply, .off or .obj");
    }
    checkOutputs(options);
    return true;
}

void writeText(const std::string& path, const std::function<void(std::ostream&)>& write) {
    writeFileAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        write(out);
        out.close();
        if (!out) throw InvalidInput("Cannot write '" + temporary + "': writing failed (disk full?).");
    });
}

void writeCorrespondence(const SkeletonGraph& skeleton, const std::string& path) {
    writeText(path, [&](std::ostream& out) {
        for (int node : skeleton.pointNode) out << node << '\n';
    });
}

}  // namespace

int main(int argc, char** argv) {
    restartWithPassiveOpenMpWaits(argv);
    Options options;
    try {
        if (!parseArguments(argc, argv, options)) {
            printHelp();
            return 0;
        }
    } catch (const UsageError& e) {
        std::fprintf(stderr, "pcskeleton: %s (see pcskeleton --help)\n", e.what());
        return 2;
    }
    try {
        // A reconstruction parameter the library would refuse is refused before the skeleton's work.
        if (!options.surface.empty()) checkReconstructionParameters(options.reconstruction);
        const PointList points = readPointCloud(options.input);
        ProgressCallback progress;
        const bool showProgress = !options.quiet && isatty(fileno(stderr));
        if (showProgress) {
            progress = [](int percent, const char* what) { std::fprintf(stderr, "\r%3d%% %-40s", percent, what); };
        }
        std::string report;
        // Every output is computed before any is written, so that a failure leaves none.
        std::vector<std::pair<std::string, std::function<void()>>> writes;
        SkeletonResult result;  // with --skeleton, only its skeleton: the one read
        if (!options.skeleton.empty()) {
            result.skeleton = readSkeleton(options.skeleton);
        } else {
            result = computeCurveSkeleton(points, options.parameters, progress);
            if (showProgress) std::fprintf(stderr, "\r%-46s\r", "");
            writes.emplace_back(options.output, [&] { writeSkeleton(result.skeleton, options.output); });
            if (!options.contracted.empty()) {
                writes.emplace_back(options.contracted, [&] { writePointCloud(result.contraction.contracted, options.contracted); });
            }
            if (!options.correspondence.empty()) {
                writes.emplace_back(options.correspondence, [&] { writeCorrespondence(result.skeleton, options.correspondence); });
            }
            report = describe(result.quality, commandLineTerms());
            if (!options.quiet) {
                const StageSeconds& s = result.seconds;
                std::fprintf(stderr,
                             "pcskeleton: %s: %zu points -> %s; contraction: %zu iterations, %s; "
                             "time: subsampling %.2f s, 1-rings %.2f s, contraction %.2f s, thinning %.2f s, embedding %.2f s, "
                             "finishing %.2f s\n%s\n",
                             options.input.c_str(), points.size(), describe(result.quality.topology).c_str(),
                             result.contraction.iterations.size(), describe(result.contraction.stopReason).c_str(),
                             s.subsampling, s.neighbourhoods, s.contraction, s.thinning, s.embedding, s.finishing, report.c_str());
            }
        }
        Reconstruction surface;
        if (!options.surface.empty()) {
            surface = reconstructFromSkeleton(points, result.skeleton, options.reconstruction, progress);
            if (showProgress) std::fprintf(stderr, "\r%-46s\r", "");
            writes.emplace_back(options.surface, [&] { writeTriangleMesh(surface.mesh, options.surface); });
            const std::string surfaceReport = describe(surface.report, commandLineTerms());
            if (!options.quiet) {
                std::fprintf(stderr, "pcskeleton: surface %s: %zu vertices, %zu triangles\n%s\n",
                             options.surface.c_str(), surface.mesh.vertices.size(), surface.mesh.triangles.size(),
                             surfaceReport.c_str());
            }
            report += (report.empty() ? "" : "\n") + surfaceReport;
        }
        if (!options.report.empty()) {
            writes.emplace_back(options.report, [&] { writeText(options.report, [&](std::ostream& out) { out << report << '\n'; }); });
        }
        std::vector<std::string> written;
        try {
            for (const auto& [path, write] : writes) {
                write();
                written.push_back(path);
            }
        } catch (const InvalidInput& e) {
            if (written.empty()) throw;
            std::string names;
            for (const std::string& path : written) names += (names.empty() ? "'" : ", '") + path + "'";
            throw InvalidInput(e.problem().description + " Written before it: " + names + ".");
        }
        return 0;
    } catch (const InvalidInput& e) {
        std::fprintf(stderr, "pcskeleton: %s\n", describe(e.problem(), commandLineTerms()).c_str());
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "pcskeleton: out of memory; try a subsampled cloud.\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pcskeleton: internal error: %s\n", e.what());
    }
    return 1;
}
