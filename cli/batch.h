// Many scans in one call: `pcskeleton a.ply b.ply scans/ -O out/ --jobs 2`.
//
// Each input runs in a child process of this same program (one input, the same options,
// one thread each), so that one input's failure, even a crash, is reported for that input
// while the rest go on, and so that each runs with a memory of its own.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pcskeleton_cli {

struct BatchInput {
    std::string path;
    std::vector<std::pair<std::string, std::string>> outputs;  // (option, file), -o first
};

struct BatchSettings {
    int jobs = 1;
    bool force = false;  // redo inputs whose outputs exist
    bool quiet = false;
    std::string summary;  // the summary table (.csv), or empty
    std::vector<std::string> options;  // the parameters' options, given to every input's run
};

// Runs every input; returns the exit status: 0 when none failed, 1 otherwise (with the
// list of failures on stderr). Throws std::runtime_error when the summary cannot be written.
int runBatch(const std::string& program, const std::vector<BatchInput>& inputs, const BatchSettings& settings);

// The line a child run prints on stdout for its parent: what the summary table shows.
std::string childSummaryLine(std::size_t points, int nodes, int cycles, int tips, int parts, std::size_t warnings);

}  // namespace pcskeleton_cli
