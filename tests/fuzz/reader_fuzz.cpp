// Mutation fuzzing of every file reader of the library (points and skeletons, all formats).
// Each seed file of the corpus is mutated (bit flips, interesting bytes, deleted, repeated
// or truncated ranges, numbers replaced by extreme ones) a fixed number of times with a
// fixed seed, and read back. A reader may accept a mutated file or refuse it with
// InvalidInput; anything else (another exception, a crash, a sanitizer report) is a defect.
//
//   reader_fuzz CORPUS_DIR WORK_DIR [--mutations N] [--seed S] [--isolate]
//
// The test suite runs a few thousand executions; developers run millions the same way
// (see the README). The input being read is always WORK_DIR/current.<ext>: after a crash
// it is the file to keep as a regression case in tests/data/bad_inputs/. With --isolate
// every read runs in a child process, so that a crash is counted (and its input kept as
// WORK_DIR/crash-N.<ext>) and the run goes on: slower, for long runs and old readers.
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/io/skeleton_io.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
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
    "4294967296", "18446744073709551615", "99999999999999999999", "1e308", "-1e308", "nan", "inf", "0.5", ""};
const std::vector<char> kInterestingBytes = {'\0', '\xff', '\x7f', '\x80', '\n', ' ', '-', '9', '.', 'e', '\r'};

class Mutator {
public:
    explicit Mutator(std::uint64_t seed) : random_(seed) {}

    Bytes mutate(Bytes data) {
        const int steps = 1 + int(below(4));
        for (int s = 0; s < steps; ++s) {
            if (data.empty()) data.push_back(' ');
            switch (below(7)) {
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

private:
    std::size_t below(std::size_t n) { return n == 0 ? 0 : std::size_t(random_() % n); }

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

Bytes readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: reader_fuzz CORPUS_DIR WORK_DIR [--mutations N] [--seed S]\n";
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
        total.executions += tally.executions;
        total.accepted += tally.accepted;
        total.refused += tally.refused;
        total.defects += tally.defects;
    }
    std::printf("%-30s %10s %10s %10s %8s\n", "seed file", "reads", "accepted", "refused", "defects");
    for (const auto& [name, t] : byFormat) {
        std::printf("%-30s %10ld %10ld %10ld %8ld\n", name.c_str(), t.executions, t.accepted, t.refused, t.defects);
    }
    std::printf("%-30s %10ld %10ld %10ld %8ld\n", "total", total.executions, total.accepted, total.refused,
                total.defects);
    return total.defects == 0 ? 0 : 1;
}
