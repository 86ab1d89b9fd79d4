// pcskeleton: point cloud in, curve skeleton out, from the command line. Built from
// vcg_ext alone (no Qt, no X server) for pipelines, benchmarks and headless machines.
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/parameter_settings.h>
#include <pcskeleton/core/openmp_wait_policy.h>
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>
#include <pcskeleton/io/batch_files.h>
#include <pcskeleton/io/branch_io.h>
#include <pcskeleton/io/input_file.h>
#include <pcskeleton/io/mesh_io.h>
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/io/skeleton_io.h>
#include <pcskeleton/version.h>

#include "batch.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unistd.h>
#include <utility>

using namespace pcskeleton;

namespace {

struct Options {
    std::vector<std::string> inputs;  // as given: files, folders, globs
    std::string input, output, contracted, correspondence, report;
    std::string skeleton;  // a given (edited) skeleton to reconstruct from, instead of computing one
    std::string fromContracted;  // contracted points written earlier (--contracted): thinning alone
    std::string surface;   // where to write the reconstructed surface
    std::string branches, pointBranches;  // the branch table; each point's branch
    pcskeleton::BranchOptions branchOptions;  // --up, --root
    bool branchOptionsGiven = false;
    bool paper = false;
    std::vector<std::pair<Parameter, double>> given;  // the parameter table's options, as given
    Settings settings;  // made from `paper` and `given` once all options are read
    bool quiet = false;
    bool force = false;  // replace existing output files
    // Several inputs: their outputs go into `outputFolder`, named by patterns ("{stem}_skeleton.ply").
    std::string outputFolder, summary;
    int jobs = 0;  // 0: one per core
    std::vector<std::string> passedOn;  // the options every input's run gets: parameters, --paper, --up, --root
    bool batchChild = false;  // run by a batch: print the summary line for it on stdout
    std::vector<pcskeleton_cli::BatchInput> batchInputs;  // made from the above once all options are read
    bool batch() const { return !outputFolder.empty() || inputs.size() > 1; }
};

class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A parameter's option: its name with dashes ("--max-wl").
std::string optionName(const ParameterInfo& p) {
    std::string option = "--";
    for (const char* c = p.name; *c; ++c) option += *c == '_' ? '-' : *c;
    return option;
}

// The library's advice in this tool's terms: each parameter by its option; a switch by its
// words and the option that turns it off ("refinement (--no-refine turns it off)").
std::string optionOf(Parameter parameter) {
    const ParameterInfo& p = parameterInfo(parameter);
    if (p.type != ValueType::Switch) return optionName(p);
    const std::string off = p.inverted ? optionName(p) : "--no-" + optionName(p).substr(2);
    return std::string(p.words) + " (" + off + " turns it off)";
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

// "  --name X" and the help wrapped beside it, then the default.
void printParameterHelp(const ParameterInfo& p) {
    std::string head = "  " + optionName(p);
    if (p.type == ValueType::Integer) head += " N";
    if (p.type == ValueType::Real) head += " X";
    if (p.type == ValueType::Switch) head += ", --no-" + optionName(p).substr(2);
    if (p.formerName) head += " (or --" + std::string(p.formerName) + ")";
    char value[64];
    std::snprintf(value, sizeof value, "%g", defaultValue(p.id));
    const std::string text =
        std::string(p.help) + " [" + (p.type == ValueType::Switch ? (defaultValue(p.id) != 0 ? "on" : "off") : value) + "]";
    constexpr std::size_t indent = 24, width = 80;
    // The help starts in the indent's column, after at least one space, or on the next line.
    std::string line = head;
    if (line.size() + 1 > indent) {
        std::printf("%s\n", line.c_str());
        line.clear();
    }
    line.resize(indent, ' ');
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find(' ', start);
        const std::string word = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (line.size() > indent && line.size() + 1 + word.size() > width) {
            std::printf("%s\n", line.c_str());
            line = std::string(indent, ' ');
        }
        line += (line.size() > indent ? " " : "") + word;
        if (end == std::string::npos) break;
        start = end + 1;
    }
    std::printf("%s\n", line.c_str());
}

void printHelp() {
    std::printf(
        "Usage: pcskeleton INPUT -o OUTPUT [options]             the skeleton\n"
        "       pcskeleton INPUT -o OUTPUT --surface SURFACE [...]  and the surface it gives\n"
        "       pcskeleton INPUT --skeleton SKELETON --surface SURFACE\n"
        "                                          the surface from a given (edited) skeleton\n"
        "       pcskeleton INPUT... -O FOLDER [--jobs N] [--summary FILE.csv] [options]\n"
        "                                          many scans, each one's outputs in FOLDER\n"
        "\n"
        "Extracts the curve skeleton of a point cloud by Laplacian-based contraction\n"
        "(Cao et al., SMI 2010): contraction, thinning, embedding. The paper's parameters\n"
        "are the defaults (but k: more neighbours on clouds under 1667 points); the steps\n"
        "it does not have (outlier detection, denoising, facing walls kept apart, the\n"
        "stretched-link limit, sheets' medial axes, re-centring, refinement, gap\n"
        "bridging, tip extension, the subsample of large clouds) are on by default\n"
        "because they measured better on imperfect scans, and --paper turns them all\n"
        "off and takes the paper's k. Every length is relative to the cloud's size:\n"
        "the same command works in millimetres or kilometres.\n"
        "\n"
        "INPUT      point set: .ply (ascii or binary, either byte order), .off, .obj\n"
        "           (faces are ignored, so meshes and polygon soups work), .xyz/.txt/.pts\n"
        "           (x y z per line); never modified\n"
        "-o FILE    the skeleton: .ply (vertices with radius, element edge), .obj (v and\n"
        "           l lines) or .cg (Starlab curve-skeleton format; no radius)\n"
        "\n"
        "Files and runs:\n"
        "  --contracted FILE     also write the contracted points (.ply or .xyz)\n"
        "  --correspondence FILE also write, for each input point, its node's index\n"
        "                        (one per line, 0-based, in the input's order; -1 for a\n"
        "                        point with no node, e.g. an outlier)\n"
        "  --surface FILE        also write a closed surface through the points whose\n"
        "                        inside and topology follow the skeleton (paper Sec. V):\n"
        "                        .ply (binary), .off or .obj\n"
        "  --skeleton FILE       reconstruct from this skeleton (.ply with radii, as -o\n"
        "                        writes it; .obj/.cg have none) instead of computing one\n"
        "  --from-contracted FILE\n"
        "                        thin the contracted points that --contracted wrote for\n"
        "                        this INPUT instead of contracting again: a new node\n"
        "                        spacing or refinement costs thinning alone. Give that\n"
        "                        run's --k, outlier and --contracted-points options:\n"
        "                        the subsample, outliers and 1-rings are found again\n"
        "                        with them\n"
        "  --branches FILE       also write the branch table: per branch (a chain between\n"
        "                        tips and junctions, grown from each part's lowest node\n"
        "                        along z) its parent, order, length, chord, radii, volume,\n"
        "                        angle to its parent, points and radius profile; .csv or\n"
        "                        .json\n"
        "  --point-branches FILE also write each input point's branch and place along it\n"
        "                        (0 at the base, 1 at the tip), in the input's order; .csv\n"
        "  --up X,Y,Z            with --branches: parts grow from their lowest node along\n"
        "                        this axis (default 0,0,1)\n"
        "  --root N              with --branches: the part of node N grows from it (nodes\n"
        "                        numbered as in the skeleton file, from 0)\n"
        "  --report FILE         also write the quality report to FILE\n"
        "  --paper               the paper's pipeline exactly: every step it does not have\n"
        "                        is off, then every other option given applies on top,\n"
        "                        whatever their order (--paper --refine is the paper plus\n"
        "                        refinement)\n"
        "  --force               replace output files that exist already (never the input)\n"
        "  --quiet               no progress and no summary on stderr\n"
        "  -h, --help            this text\n"
        "  --version             the version (the Python module's and the plugins' too)\n"
        "\n"
        "Several inputs (files, folders of point files, globs such as 'scans/*.ply'):\n"
        "  -O FOLDER             write each input's outputs into FOLDER (made if missing);\n"
        "                        every output option is then a file name in which {stem}\n"
        "                        stands for the input's name: -o defaults to\n"
        "                        {stem}_skeleton.ply, and e.g. --branches\n"
        "                        {stem}_branches.csv adds a table per input. Inputs of\n"
        "                        one name in different folders are told apart by their\n"
        "                        folder (a_scan, b_scan)\n"
        "  --jobs N              inputs run side by side, one thread each [one per core]\n"
        "  --summary FILE        a table of the batch (.csv): input, points, nodes, cycles,\n"
        "                        tips, parts, warnings, seconds, status, message\n"
        "  An input whose outputs all exist is skipped (--force redoes it), so a rerun of\n"
        "  the same command resumes. One input's failure is reported and the rest go on;\n"
        "  the exit status is then 1, with the list of failures.\n"
        "\n"
        "After the run a quality report goes to stderr: cycles, tips, junctions, parts,\n"
        "whether contraction converged, and warnings (points that did not contract, parts\n"
        "that gave no bone, nodes outside the shape, short spurs, loops without a hole),\n"
        "each naming the option that usually fixes it.\n");
    const struct {
        Stage stage;
        const char* title;
    } sections[] = {{Stage::Contraction, "Contraction (paper Sec. III-A)"},
                    {Stage::PointCleaning, "Which points are contracted"},
                    {Stage::Resolution, "Large clouds"},
                    {Stage::Thinning, "Thinning (paper Sec. III-B) and the steps after it"},
                    {Stage::Reconstruction, "Surface (paper Sec. V; with --surface)"}};
    for (const auto& section : sections) {
        std::printf("\n%s, default in brackets:\n", section.title);
        for (bool advanced : {false, true}) {
            for (const ParameterInfo& p : parameterTable()) {
                if (p.stage == section.stage && p.advanced == advanced) printParameterHelp(p);
            }
        }
    }
    std::printf(
        "\n"
        "Each option is also a keyword of the Python module (--max-wl X is max_wl=X).\n"
        "\n"
        "Files: the input is never modified. An output that exists already is refused\n"
        "unless --force is given; an output naming the input is always refused. Each\n"
        "output appears only once complete (written aside, then renamed).\n"
        "\n"
        "Exit status: 0 on success, 1 when the input cannot be processed (the reason is\n"
        "printed on one line), 2 on a command-line error.\n");
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

// A path's canonical form; none for a name that cannot be resolved (a symlink loop),
// which names no other file.
std::optional<std::string> canonicalPath(const std::string& path) {
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
    if (error) return std::nullopt;
    return canonical.string();
}

// The file a path names, for comparing: its canonical form when it has one.
std::string canonicalName(const std::string& path) { return canonicalPath(path).value_or(path); }

bool samePath(const std::string& a, const std::string& b) {
    if (sameFile(a, b)) return true;
    const std::optional<std::string> x = canonicalPath(a);
    return x && x == canonicalPath(b);
}

// The files some paths name, each looked up once, to ask of many other paths whether they
// name one of them (as samePath would with each): a batch checks every output against
// every input, and pairwise that grows with the square of a batch.
class PathSet {
public:
    explicit PathSet(const std::vector<std::string>& paths) {
        for (const std::string& path : paths) {
            if (const auto identity = fileIdentity(path)) identities_.insert(*identity);
            if (const auto name = canonicalPath(path)) names_.insert(*name);
        }
    }
    bool holds(const std::string& path) const {
        const auto identity = fileIdentity(path);
        if (identity && identities_.count(*identity)) return true;
        const auto name = canonicalPath(path);
        return name && names_.count(*name);
    }

private:
    std::set<FileIdentity> identities_;
    std::set<std::string> names_;
};

// Every output option and its file (with several inputs, its name pattern); -o first.
std::vector<std::pair<std::string, std::string>> outputOptions(const Options& options) {
    return {{"-o", options.output},         {"--contracted", options.contracted},
            {"--correspondence", options.correspondence}, {"--report", options.report},
            {"--surface", options.surface}, {"--branches", options.branches},
            {"--point-branches", options.pointBranches}};
}

// Before any work: no output may be the input or another output, an existing output is
// replaced only with --force, and each output's folder must exist.
void checkOutputs(const Options& options) {
    const std::vector<std::pair<std::string, std::string>> outputs = outputOptions(options);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& [option, path] = outputs[i];
        if (path.empty()) continue;
        for (const std::string& input : {options.input, options.skeleton, options.fromContracted}) {
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

// Each output's kind from its name's extension.
void checkOutputNames(const Options& options) {
    if (!options.surface.empty() && !isMeshFileName(options.surface)) {
        throw UsageError("the surface must end in .ply, .off or .obj");
    }
    if (!options.branches.empty() && !isBranchTableFileName(options.branches)) {
        throw UsageError("the branch table must end in .csv or .json");
    }
    if (!options.pointBranches.empty() && extensionOf(options.pointBranches) != "csv") {
        throw UsageError("the points' branches must end in .csv");
    }
    if (options.branchOptionsGiven && options.branches.empty() && options.pointBranches.empty()) {
        throw UsageError("--up and --root choose where branches grow from: add --branches FILE or --point-branches FILE");
    }
}

// Several inputs: every output option is a name pattern inside the output folder, "{stem}"
// standing for the input's name; the plan is checked whole before any work (no output may
// be an input, nor two outputs one file).
void checkBatch(Options& options) {
    if (options.outputFolder.empty()) {
        throw UsageError("several inputs ('" + options.inputs[0] + "', '" + options.inputs[1] +
                         "', ...): add -O FOLDER for their outputs");
    }
    if (!options.skeleton.empty()) throw UsageError("--skeleton takes one input: leave out -O and the other inputs");
    if (!options.fromContracted.empty()) {
        throw UsageError("--from-contracted takes one input: leave out -O and the other inputs");
    }
    if (options.output.empty()) options.output = "{stem}_skeleton.ply";
    if (!isSkeletonFileName(options.output)) throw UsageError("the output must end in .ply, .obj or .cg");
    checkOutputNames(options);
    std::vector<std::string> inputs;
    try {
        inputs = expandInputs(options.inputs);
    } catch (const std::exception& e) {
        throw UsageError(e.what());
    }
    const std::vector<std::pair<std::string, std::string>> patterns = outputOptions(options);
    for (const auto& [option, pattern] : patterns) {
        if (pattern.empty()) continue;
        if (pattern.find('/') != std::string::npos) {
            throw UsageError(option + " '" + pattern + "': with -O, give a file name (the folder is -O's)");
        }
        if (inputs.size() > 1 && pattern.find("{stem}") == std::string::npos) {
            throw UsageError(option + " '" + pattern + "' would name one file for every input: put {stem} in it, e.g. {stem}_" +
                             pattern);
        }
    }
    const std::vector<std::string> stems = outputStems(inputs);
    const PathSet inputFiles(inputs);
    std::map<std::string, std::string> outputOf;  // each output file: the input it is for
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        pcskeleton_cli::BatchInput batchInput{inputs[i], {}};
        for (const auto& [option, pattern] : patterns) {
            if (pattern.empty()) continue;
            const std::string path = (std::filesystem::path(options.outputFolder) /
                                      fromPattern(pattern, stems[i])).string();
            if (inputFiles.holds(path)) {
                throw UsageError(option + " would write '" + path + "', which is an input; choose another -O or " +
                                 option + " (inputs are never overwritten)");
            }
            if (!outputOf.emplace(canonicalName(path), inputs[i]).second) {
                throw UsageError("two outputs would be '" + path + "'; give each output option its own pattern");
            }
            batchInput.outputs.emplace_back(option, path);
        }
        options.batchInputs.push_back(std::move(batchInput));
    }
    if (!options.summary.empty()) {
        if (extensionOf(options.summary) != "csv") throw UsageError("the summary must end in .csv");
        if (inputFiles.holds(options.summary)) throw UsageError("--summary '" + options.summary + "' is an input");
        if (outputOf.count(canonicalName(options.summary))) {
            throw UsageError("--summary '" + options.summary + "' is also one of the outputs");
        }
    }
    std::error_code error;
    std::filesystem::create_directories(options.outputFolder, error);
    if (!std::filesystem::is_directory(options.outputFolder)) {
        throw UsageError("-O '" + options.outputFolder + "' is not a folder and cannot be made one" +
                         (error ? ": " + error.message() : std::string()));
    }
}

// Returns false when --help was given.
bool parseArguments(int argc, char** argv, Options& options) {
    const std::map<std::string, std::string*> files = {
        {"-o", &options.output},           {"--output", &options.output},
        {"--contracted", &options.contracted}, {"--correspondence", &options.correspondence},
        {"--report", &options.report},     {"--skeleton", &options.skeleton},
        {"--from-contracted", &options.fromContracted},
        {"--surface", &options.surface},   {"--branches", &options.branches},
        {"--point-branches", &options.pointBranches}};
    // The parameter table's options: "--name VALUE", or for a switch "--name" and "--no-name".
    std::map<std::string, std::pair<const ParameterInfo*, int>> parameters;  // value: -1 = read one
    for (const ParameterInfo& p : parameterTable()) {
        std::vector<std::string> names = {optionName(p)};
        if (p.formerName) names.push_back("--" + std::string(p.formerName));
        for (const std::string& name : names) {
            if (p.type == ValueType::Switch) {
                parameters[name] = {&p, 1};
                parameters["--no-" + name.substr(2)] = {&p, 0};
            } else {
                parameters[name] = {&p, -1};
            }
        }
    }
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw UsageError(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "-h" || arg == "--help") return false;
        if (arg == "--version") {
            std::printf("pcskeleton %s\n", PCSKELETON_VERSION);
            std::exit(0);
        }
        if (arg == "--quiet") {
            options.quiet = true;
        } else if (arg == "--force") {
            options.force = true;
        } else if (arg == "--batch-child") {
            options.batchChild = true;
        } else if (arg == "--paper") {
            options.paper = true;
            options.passedOn.push_back(arg);
        } else if (arg == "-O" || arg == "--output-folder") {
            options.outputFolder = value();
        } else if (arg == "--summary") {
            options.summary = value();
        } else if (arg == "--jobs") {
            options.jobs = parseInteger(arg, value());
            if (options.jobs < 1) throw UsageError("--jobs expects 1 or more runs at a time");
        } else if (arg == "--up" || arg == "--root") {
            const std::string text = value();
            options.passedOn.insert(options.passedOn.end(), {arg, text});
            options.branchOptionsGiven = true;
            if (arg == "--root") {
                options.branchOptions.root = parseInteger(arg, text);
            } else {
                std::vector<double> axis;
                std::size_t start = 0;
                for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1) {
                    axis.push_back(parseNumber(arg, text.substr(start, comma - start)));
                }
                axis.push_back(parseNumber(arg, text.substr(start)));
                if (axis.size() != 3) throw UsageError("--up expects three numbers X,Y,Z, got '" + text + "'");
                options.branchOptions.up = Point(axis[0], axis[1], axis[2]);
                if (!options.branchOptions.up.allFinite() || !(options.branchOptions.up.norm() > 0.0)) {
                    throw UsageError("--up " + text + " has no direction: give one such as 0,0,1");
                }
            }
        } else if (auto file = files.find(arg); file != files.end()) {
            *file->second = value();
        } else if (auto parameter = parameters.find(arg); parameter != parameters.end()) {
            const auto [info, fixed] = parameter->second;
            options.passedOn.push_back(arg);
            if (fixed >= 0) {
                options.given.emplace_back(info->id, fixed);
            } else {
                const std::string text = value();
                options.passedOn.push_back(text);
                options.given.emplace_back(info->id, info->type == ValueType::Integer ? parseInteger(arg, text)
                                                                                      : parseNumber(arg, text));
            }
        } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
            throw UsageError("unknown option " + arg);
        } else {
            options.inputs.push_back(arg);
        }
    }
    if (options.inputs.empty()) throw UsageError("no input file");
    if (options.batch()) return checkBatch(options), true;
    if (options.jobs > 0 || !options.summary.empty()) {
        throw UsageError("--jobs and --summary are for several inputs: add -O FOLDER for their outputs");
    }
    options.input = options.inputs.front();
    if (!options.fromContracted.empty()) {
        if (!options.skeleton.empty()) throw UsageError("--skeleton and --from-contracted: give one of them");
        if (!options.contracted.empty()) {
            throw UsageError("--contracted with --from-contracted: the contracted points are that file already");
        }
    }
    if (!options.skeleton.empty()) {
        if (options.surface.empty() && options.branches.empty()) {
            throw UsageError("--skeleton is for reconstruction or measuring: add --surface FILE or --branches FILE");
        }
        if (!options.output.empty() || !options.contracted.empty() || !options.correspondence.empty() ||
            !options.pointBranches.empty()) {
            throw UsageError("with --skeleton no skeleton is computed: leave out -o, --contracted, --correspondence "
                             "and --point-branches");
        }
    } else {
        if (options.output.empty()) throw UsageError("no output file (-o FILE)");
        if (!isSkeletonFileName(options.output)) throw UsageError("the output must end in .ply, .obj or .cg");
    }
    checkOutputNames(options);
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
        // Every value is checked here, before any work.
        options.settings = settingsFrom(options.paper, options.given);
        if (options.batch()) {
            pcskeleton_cli::BatchSettings batch;
            batch.jobs = options.jobs > 0 ? options.jobs : int(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
            batch.force = options.force;
            batch.quiet = options.quiet;
            batch.summary = options.summary;
            batch.options = options.passedOn;
            try {
                return pcskeleton_cli::runBatch("/proc/self/exe", options.batchInputs, batch);
            } catch (const std::runtime_error& e) {  // the batch itself, not one of its inputs
                std::fprintf(stderr, "pcskeleton: %s\n", e.what());
                return 1;
            }
        }
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
            if (options.fromContracted.empty()) {
                result = computeCurveSkeleton(points, options.settings.skeleton, progress);
            } else {
                result = skeletonFromContractedPoints(points, readPointCloud(options.fromContracted),
                                                      options.settings.skeleton, progress);
            }
            if (showProgress) std::fprintf(stderr, "\r%-46s\r", "");
            writes.emplace_back(options.output, [&] { writeSkeleton(result.skeleton, options.output); });
            if (!options.contracted.empty()) {
                writes.emplace_back(options.contracted, [&] { writePointCloud(result.contraction.contracted, options.contracted); });
            }
            if (!options.correspondence.empty()) {
                writes.emplace_back(options.correspondence, [&] { writeCorrespondence(result.skeleton, options.correspondence); });
            }
            report = describe(result.quality, commandLineTerms());
            if (options.batchChild) {
                const SkeletonTopology& t = result.quality.topology;
                std::printf("%s\n", pcskeleton_cli::childSummaryLine(points.size(), t.nodes, t.cycles, t.tips, t.components,
                                                                      result.quality.warnings().size()).c_str());
            }
            if (!options.quiet) {
                const StageSeconds& s = result.seconds;
                const std::string contraction =
                    options.fromContracted.empty()
                        ? std::to_string(result.contraction.iterations.size()) + " iterations, " +
                              describe(result.contraction.stopReason)
                        : "read from " + options.fromContracted;
                std::fprintf(stderr,
                             "pcskeleton: %s: %zu points -> %s; contraction: %s; "
                             "time: subsampling %.2f s, 1-rings %.2f s, contraction %.2f s, thinning %.2f s, embedding %.2f s, "
                             "finishing %.2f s\n%s\n",
                             options.input.c_str(), points.size(), describe(result.quality.topology).c_str(),
                             contraction.c_str(), s.subsampling, s.neighbourhoods, s.contraction, s.thinning, s.embedding,
                             s.finishing, report.c_str());
            }
        }
        SkeletonBranches branches;
        if (!options.branches.empty() || !options.pointBranches.empty()) {
            // A skeleton read with --skeleton has no correspondence to the points.
            branches = result.skeleton.pointNode.size() == points.size()
                           ? measureBranches(result.skeleton, points, options.branchOptions)
                           : measureBranches(result.skeleton, options.branchOptions);
            if (!options.branches.empty()) writes.emplace_back(options.branches, [&] { writeBranchTable(branches, options.branches); });
            if (!options.pointBranches.empty()) {
                writes.emplace_back(options.pointBranches, [&] { writePointBranches(branches, options.pointBranches); });
            }
            const std::string line = "Branches: " + describe(branches) + ".";
            if (!options.quiet) std::fprintf(stderr, "%s\n", line.c_str());
            report += (report.empty() ? "" : "\n") + line;
        }
        Reconstruction surface;
        if (!options.surface.empty()) {
            surface = reconstructFromSkeleton(points, result.skeleton, options.settings.reconstruction, progress);
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
