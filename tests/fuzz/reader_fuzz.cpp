// Mutation fuzzing of every file reader of the library (points and skeletons, all formats).
// Each seed file of the corpus is mutated (bit flips, interesting bytes, deleted, repeated
// or truncated ranges, numbers replaced by extreme ones) a fixed number of times with a
// fixed seed, and read back. A reader may accept a mutated file or refuse it with
// InvalidInput; anything else (another exception, a crash, a sanitizer report) is a defect.
//
//   reader_fuzz CORPUS_DIR WORK_DIR [--mutations N] [--seed S] [--isolate] [--locale NAME]
//
// Beyond crashes, oracles for misreads: a decimal comma in a line of coordinates, or an
// ascii PLY vertex line with a value more or fewer than its header, must be refused. Then
// as many output paths as mutations are written or refused, never leaving a file behind.
//
// The test suite runs a few thousand executions; developers run millions the same way
// (see docs/tests.md). The input being read is always WORK_DIR/current.<ext>: after a crash
// it is the file to keep as a regression case in tests/data/bad_inputs/. With --isolate
// every read runs in a child process, so that a crash is counted (and its input kept as
// WORK_DIR/crash-N.<ext>) and the run goes on: slower, for long runs and old readers.
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/io/input_file.h>
#include <pcskeleton/io/skeleton_io.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <clocale>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <typeinfo>
#include <vector>

namespace fs = std::filesystem;
using Bytes = std::string;

namespace {

const std::vector<std::string> kInterestingNumbers = {
    "-1", "0", "1", "255", "256", "65536", "2147483647", "2147483648", "-2147483648", "4294967295",
    "4294967296", "18446744073709551615", "99999999999999999999", "1e308", "-1e308", "nan", "inf", "0.5", "",
    // Beyond a double's range either way, subnormal, signed, hexadecimal, a decimal comma.
    "1e400", "-1e400", "1e-400", "4.9e-324", "1e-310", "+1.5", "1E+308", "0x10", "1,5", "-0"};
const std::vector<char> kInterestingBytes = {'\0', '\xff', '\x7f', '\x80', '\n', ' ', '-', '9', '.', 'e', '\r'};

class Mutator {
public:
    explicit Mutator(std::uint64_t seed) : random_(seed) {}

    Bytes mutate(Bytes data) {
        const int steps = 1 + int(below(4));
        for (int s = 0; s < steps; ++s) {
            if (data.empty()) data.push_back(' ');
            switch (below(9)) {
                case 0: data[below(data.size())] ^= char(1u << below(8)); break;
                case 1: data[below(data.size())] = kInterestingBytes[below(kInterestingBytes.size())]; break;
                case 2: {  // delete a range
                    const std::size_t at = below(data.size());
                    data.erase(at, 1 + below(std::min<std::size_t>(64, data.size() - at)));
                    break;
                }
                case 3: {  // repeat a range somewhere else
                    const std::size_t from = below(data.size());
                    const Bytes piece = data.substr(from, 1 + below(64));
                    data.insert(below(data.size() + 1), piece);
                    break;
                }
                case 4: data.resize(below(data.size() + 1)); break;  // truncate
                case 5: replaceNumber(data); break;
                case 7: changeRecordLength(data, below(data.size())); break;
                case 8: decimalCommas(data, below(data.size())); break;
                default: {  // a 4-byte binary value replaced by an extreme one
                    const std::uint32_t values[] = {0u, 0xffffffffu, 0x7fffffffu, 0x80000000u, 0xffu, 0x7f800000u};
                    const std::size_t at = below(data.size());
                    const std::uint32_t v = values[below(6)];
                    for (std::size_t b = 0; b < 4 && at + b < data.size(); ++b) data[at + b] = char(v >> (8 * b));
                }
            }
        }
        return data;
    }

    // The line holding byte `at` loses its last value or gains one (an ascii record longer
    // or shorter than its header says).
    void changeRecordLength(Bytes& data, std::size_t at) {
        const auto [begin, end] = lineAround(data, at);
        if (below(2) == 0) {
            const std::size_t blank = data.find_last_of(" \t", end == begin ? begin : end - 1);
            if (blank != std::string::npos && blank >= begin) data.erase(blank, end - blank);
        } else {
            data.insert(end, " 7");
        }
    }

    // Every decimal point of the line holding byte `at` becomes a comma ("1.5" -> "1,5").
    static void decimalCommas(Bytes& data, std::size_t at) {
        const auto [begin, end] = lineAround(data, at);
        for (std::size_t i = begin + 1; i + 1 < end; ++i) {
            if (data[i] == '.' && std::isdigit(static_cast<unsigned char>(data[i - 1])) &&
                std::isdigit(static_cast<unsigned char>(data[i + 1]))) {
                data[i] = ',';
            }
        }
    }

    // [begin, end) of the line holding byte `at`, without its newline.
    static std::pair<std::size_t, std::size_t> lineAround(const Bytes& data, std::size_t at) {
        if (data.empty()) return {0, 0};
        at = std::min(at, data.size() - 1);
        const std::size_t previous = at == 0 ? std::string::npos : data.rfind('\n', at - 1);
        const std::size_t begin = previous == std::string::npos ? 0 : previous + 1;
        const std::size_t end = std::min(data.find('\n', begin), data.size());
        return {begin, end};
    }

    std::size_t below(std::size_t n) { return n == 0 ? 0 : std::size_t(random_() % n); }

private:

    // Replaces one run of digits (with its sign) by an interesting number.
    void replaceNumber(Bytes& data) {
        std::vector<std::size_t> starts;
        for (std::size_t i = 0; i < data.size(); ++i) {
            if (std::isdigit(static_cast<unsigned char>(data[i])) &&
                (i == 0 || !std::isdigit(static_cast<unsigned char>(data[i - 1])))) {
                starts.push_back(i);
            }
        }
        if (starts.empty()) return;
        std::size_t begin = starts[below(starts.size())], end = begin;
        while (end < data.size() && (std::isdigit(static_cast<unsigned char>(data[end])) || data[end] == '.')) ++end;
        if (begin > 0 && data[begin - 1] == '-') --begin;
        data.replace(begin, end - begin, kInterestingNumbers[below(kInterestingNumbers.size())]);
    }

    std::mt19937_64 random_;
};

struct Tally {
    long executions = 0, accepted = 0, refused = 0, defects = 0;
};

enum Outcome { Accepted, Refused, Defect };

Outcome readOnce(const std::string& path, const std::function<void()>& read) {
    try {
        read();
        return Accepted;
    } catch (const pcskeleton::InvalidInput&) {
        return Refused;
    } catch (const std::exception& e) {
        std::cerr << "DEFECT: " << path << ": " << typeid(e).name() << ": " << e.what() << '\n';
        return Defect;
    }
}

bool isolate = false;
long crashes = 0;

// readOnce() in a child process: a crash or a hang becomes a Defect, with the input kept.
Outcome readIsolated(const std::string& path, const std::function<void()>& read) {
    const pid_t child = fork();
    if (child == 0) {
        alarm(10);
        _exit(readOnce(path, read));
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) <= Defect) return Outcome(WEXITSTATUS(status));
    const fs::path kept = fs::path(path).replace_filename("crash-" + std::to_string(++crashes) +
                                                         fs::path(path).extension().string());
    fs::copy_file(path, kept, fs::copy_options::overwrite_existing);
    std::cerr << "DEFECT: " << (WIFSIGNALED(status) ? "signal " + std::to_string(WTERMSIG(status))
                                                    : "exit " + std::to_string(WEXITSTATUS(status)))
              << " reading " << kept << '\n';
    return Defect;
}

// Reads the file with every reader its extension has; counts the outcomes.
void readWithEveryReader(const std::string& path, bool isSkeletonFormat, Tally& tally) {
    const auto attempt = [&](const std::function<void()>& read) {
        ++tally.executions;
        switch (isolate ? readIsolated(path, read) : readOnce(path, read)) {
            case Accepted: ++tally.accepted; break;
            case Refused: ++tally.refused; break;
            case Defect: ++tally.defects; break;
        }
    };
    if (pcskeleton::isPointCloudFileName(path)) attempt([&] { pcskeleton::readPointCloud(path); });
    if (isSkeletonFormat) attempt([&] { pcskeleton::readSkeleton(path); });
}

// The byte offsets of the lines every reader of the file reads as numbers: an ascii PLY's
// first element (the vertices) and the coordinate lines of the text formats.
std::vector<std::size_t> numberLines(const Bytes& data, const std::string& ext) {
    std::vector<std::size_t> lines;
    std::size_t begin = 0;
    long plyRecords = -1;  // vertex lines still to come after end_header; -1 before it
    long declared = 0;
    bool ply = ext == ".ply";
    if (ply && data.find("format ascii") == std::string::npos) return lines;
    for (std::size_t line = 0; begin < data.size(); ++line) {
        const std::size_t end = std::min(data.find('\n', begin), data.size());
        const std::string text = data.substr(begin, end - begin);
        if (ply) {
            if (plyRecords > 0) lines.push_back(begin), --plyRecords;
            if (plyRecords < 0 && declared == 0 && text.rfind("element vertex ", 0) == 0) declared = std::atol(text.c_str() + 15);
            if (text == "end_header") plyRecords = declared;
        } else if (ext == ".xyz" || (ext == ".off" && line >= 2)) {
            if (!text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-')) lines.push_back(begin);
        } else if ((ext == ".obj" || ext == ".cg") && text.rfind("v ", 0) == 0) {
            lines.push_back(begin);
        }
        begin = end + 1;
    }
    return lines;
}

// Mutations no reader may accept, as accepting them would misread the file: a decimal
// comma in a line of coordinates with decimals, and (ascii PLY) a vertex line with a value
// more or fewer than the header declares.
void checkMisreadOracles(const Bytes& original, const std::string& ext, const std::string& current,
                         bool isSkeletonFormat, Mutator& mutator, long mutations, Tally& tally) {
    const std::vector<std::size_t> lines = numberLines(original, ext);
    if (lines.empty()) return;
    for (long m = 0; m < mutations; ++m) {
        Bytes data = original;
        const std::size_t at = lines[mutator.below(lines.size())];
        const bool comma = ext != ".ply" || mutator.below(2) == 0;
        if (comma) {
            Mutator::decimalCommas(data, at);
            if (data == original) continue;  // no decimals on that line
        } else {
            mutator.changeRecordLength(data, at);
        }
        std::ofstream(current, std::ios::binary | std::ios::trunc) << data;
        const Tally before = tally;
        readWithEveryReader(current, isSkeletonFormat, tally);
        if (tally.accepted != before.accepted) {
            std::cerr << "DEFECT: misread, accepted with " << (comma ? "decimal commas" : "a record of another length")
                      << " at byte " << at << ": kept as " << current << ".misread\n";
            fs::copy_file(current, current + ".misread", fs::copy_options::overwrite_existing);
            tally.defects += tally.accepted - before.accepted;
            tally.accepted = before.accepted;
        }
    }
}

// Output paths put together from awkward pieces (names too long, symbolic-link loops,
// missing or unwritable folders, a directory, "..", blanks and newlines) are written
// through every writer or refused with InvalidInput; a refused write leaves nothing
// behind, an accepted one the whole file and no temporary.
void fuzzOutputPaths(const fs::path& work, Mutator& mutator, long paths, Tally& tally) {
    const fs::path root = work / "paths";
    fs::remove_all(root);
    fs::create_directories(root / "folder");
    fs::create_symlink("loop", root / "loop");
    fs::create_symlink("folder", root / "link");
    const std::vector<std::string> folders = {"", "folder/", "link/", "loop/", "missing/", "folder/../", "/proc/",
                                              "folder/sub/missing/", std::string(300, 'f') + "/"};
    const std::vector<std::string> names = {"s", std::string(250, 'n'), std::string(260, 'n'), "two words", "line\nbreak",
                                            "folder", "loop", ".", "..", "-dash", "x.partial-1-abcdef", ""};
    const std::vector<std::string> extensions = {".ply", ".obj", ".cg", ".xyz", "", ".PLY", ".ply/"};
    pcskeleton::SkeletonGraph skeleton;
    skeleton.nodes = {pcskeleton::Point(0, 0, 0), pcskeleton::Point(1, 0, 0)};
    skeleton.radii = {0.1, 0.1};
    skeleton.edges = {{0, 1}};
    const auto entries = [&] {
        std::size_t count = 0;
        for (auto it = fs::recursive_directory_iterator(root, fs::directory_options::skip_permission_denied);
             it != fs::recursive_directory_iterator(); ++it) {
            ++count;
        }
        return count;
    };
    const std::size_t before = entries();
    for (long p = 0; p < paths; ++p) {
        const std::string relative = folders[mutator.below(folders.size())] + names[mutator.below(names.size())] +
                                     extensions[mutator.below(extensions.size())];
        const std::string path = relative.front() == '/' ? relative : (root / relative).string();
        const bool asSkeleton = mutator.below(2) == 0;
        ++tally.executions;
        std::error_code ignored;
        const bool existed = fs::exists(fs::symlink_status(path, ignored));
        switch (readOnce(path, [&] {
            pcskeleton::checkWritable(path);
            if (asSkeleton) pcskeleton::writeSkeleton(skeleton, path);
            else pcskeleton::writePointCloud(skeleton.nodes, path);
        })) {
            case Accepted:
                ++tally.accepted;
                if (!fs::is_regular_file(path, ignored)) {
                    std::cerr << "DEFECT: writing '" << path << "' was accepted but wrote no file\n";
                    ++tally.defects;
                }
                if (!existed) fs::remove(path, ignored);
                break;
            case Refused: ++tally.refused; break;
            case Defect: ++tally.defects; break;
        }
        if (entries() != before) {
            std::cerr << "DEFECT: writing '" << path << "' left a file behind\n";
            ++tally.defects;
            fs::remove_all(root);
            return;
        }
    }
    fs::remove_all(root);
}

Bytes readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: reader_fuzz CORPUS_DIR WORK_DIR [--mutations N] [--seed S] [--isolate] [--locale NAME]\n";
        return 2;
    }
    const fs::path corpus = argv[1], work = argv[2];
    long mutations = 300;
    std::uint64_t seed = 1;
    for (int i = 3; i < argc; ++i) {
        const std::string option = argv[i];
        if (option == "--isolate") isolate = true;
        else if (option == "--mutations" && i + 1 < argc) mutations = std::atol(argv[++i]);
        else if (option == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
        else if (option == "--locale" && i + 1 < argc) {
            // The readers must read the same in a locale with a decimal comma (MeshLab runs in the user's).
            const char* name = argv[++i];
            if (!std::setlocale(LC_ALL, name)) { std::cerr << "no locale " << name << '\n'; return 2; }
        }
        else { std::cerr << "unknown option " << option << '\n'; return 2; }
    }
    fs::create_directories(work);
    std::vector<fs::path> seeds;
    for (const auto& entry : fs::directory_iterator(corpus)) seeds.push_back(entry.path());
    std::sort(seeds.begin(), seeds.end());
    if (seeds.empty()) {
        std::cerr << "no seed files in " << corpus << '\n';
        return 2;
    }

    std::map<std::string, Tally> byFormat;
    Tally total;
    for (std::size_t s = 0; s < seeds.size(); ++s) {
        const Bytes original = readAll(seeds[s]);
        const std::string ext = seeds[s].extension().string();
        const std::string current = (work / ("current" + ext)).string();
        const bool isSkeletonFormat = pcskeleton::isSkeletonFileName(current);
        Mutator mutator(seed * 1000003u + s);
        Tally& tally = byFormat[seeds[s].filename().string()];
        for (long m = 0; m <= mutations; ++m) {  // m = 0: the seed itself, which must be read
            const Bytes data = m == 0 ? original : mutator.mutate(original);
            std::ofstream(current, std::ios::binary | std::ios::trunc) << data;
            Tally before = tally;
            readWithEveryReader(current, isSkeletonFormat, tally);
            if (m == 0 && tally.accepted == before.accepted) {
                std::cerr << "DEFECT: the unmutated seed " << seeds[s] << " was not read\n";
                ++tally.defects;
            }
        }
        checkMisreadOracles(original, ext, current, isSkeletonFormat, mutator, mutations / 4, tally);
        total.executions += tally.executions;
        total.accepted += tally.accepted;
        total.refused += tally.refused;
        total.defects += tally.defects;
    }
    Mutator pathMutator(seed);
    Tally& paths = byFormat["(output paths)"];
    fuzzOutputPaths(work, pathMutator, mutations, paths);
    total.executions += paths.executions;
    total.accepted += paths.accepted;
    total.refused += paths.refused;
    total.defects += paths.defects;
    std::printf("%-30s %10s %10s %10s %8s\n", "seed file", "reads", "accepted", "refused", "defects");
    for (const auto& [name, t] : byFormat) {
        std::printf("%-30s %10ld %10ld %10ld %8ld\n", name.c_str(), t.executions, t.accepted, t.refused, t.defects);
    }
    std::printf("%-30s %10ld %10ld %10ld %8ld\n", "total", total.executions, total.accepted, total.refused,
                total.defects);
    return total.defects == 0 ? 0 : 1;
}
