#include "batch.h"

#include <pcskeleton/io/input_file.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <poll.h>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace pcskeleton_cli {

namespace {

// A comma-separated field, quoted when it needs to be.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
    return quoted + "\"";
}

const char* const kSummaryHeader = "input,points,nodes,cycles,tips,parts,warnings,seconds,status,message";
const char* const kChildSummaryMark = "pcskeleton-batch-row";

struct Row {
    std::string input;
    std::string status = "waiting";  // ok, failed, skipped
    std::string message;
    std::map<std::string, std::string> values;  // points, nodes, ... as the child printed them
    double seconds = 0.0;
};

// A child run's output: its summary line's values, and its last other line (the reason it
// failed, without the program's name).
void readChildOutput(const std::string& output, Row& row) {
    std::istringstream lines(output);
    std::string line, last;
    while (std::getline(lines, line)) {
        if (line.rfind(kChildSummaryMark, 0) == 0) {
            std::istringstream fields(line.substr(std::strlen(kChildSummaryMark)));
            std::string field;
            while (fields >> field) {
                const std::size_t equals = field.find('=');
                if (equals != std::string::npos) row.values[field.substr(0, equals)] = field.substr(equals + 1);
            }
        } else if (!line.empty()) {
            last = line;
        }
    }
    const std::string prefix = "pcskeleton: ";
    row.message = last.rfind(prefix, 0) == 0 ? last.substr(prefix.size()) : last;
}

// The environment of a child: the parent's, with one thread for OpenMP and for BLAS (the
// batch runs its inputs side by side, one per core).
std::vector<std::string> childEnvironment() {
    std::vector<std::string> variables;
    for (char** v = environ; *v; ++v) {
        const std::string variable = *v;
        if (variable.rfind("OMP_NUM_THREADS=", 0) != 0 && variable.rfind("OPENBLAS_NUM_THREADS=", 0) != 0) {
            variables.push_back(variable);
        }
    }
    variables.push_back("OMP_NUM_THREADS=1");
    variables.push_back("OPENBLAS_NUM_THREADS=1");
    return variables;
}

std::vector<char*> pointersTo(std::vector<std::string>& strings) {
    std::vector<char*> pointers;
    for (std::string& s : strings) pointers.push_back(s.data());
    pointers.push_back(nullptr);
    return pointers;
}

struct Child {
    pid_t pid = -1;
    int output = -1;  // the read end of its stdout and stderr
    std::size_t row = 0;
    std::string text;
    std::chrono::steady_clock::time_point start;
};

Child startChild(const std::string& program, std::vector<std::string> arguments, std::vector<std::string>& environment,
                 std::size_t row) {
    int pipeEnds[2];
    if (pipe(pipeEnds) != 0) throw std::runtime_error(std::string("cannot start a run: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipeEnds[0]);
    posix_spawn_file_actions_addclose(&actions, pipeEnds[1]);
    Child child;
    child.row = row;
    child.start = std::chrono::steady_clock::now();
    const std::vector<char*> argv = pointersTo(arguments);
    const std::vector<char*> envp = pointersTo(environment);
    const int failed = posix_spawn(&child.pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    close(pipeEnds[1]);
    if (failed != 0) {
        close(pipeEnds[0]);
        throw std::runtime_error("cannot start '" + program + "': " + std::strerror(failed));
    }
    child.output = pipeEnds[0];
    return child;
}

// Reaps a child whose output ended, and fills its row.
void finishChild(Child& child, Row& row) {
    close(child.output);
    int status = 0;
    while (waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
    }
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - child.start).count();
    readChildOutput(child.text, row);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        row.status = "ok";
        row.message.clear();
    } else {
        row.status = "failed";
        if (WIFSIGNALED(status)) {
            row.message = "the run crashed (signal " + std::to_string(WTERMSIG(status)) + ": " + strsignal(WTERMSIG(status)) +
                          ")" + (row.message.empty() ? "" : "; its last words: " + row.message);
        } else if (row.message.empty()) {
            row.message = "the run failed without a message (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
        }
    }
}

class Progress {
public:
    Progress(std::size_t total, bool quiet) : total_(total), quiet_(quiet), tty_(isatty(STDERR_FILENO)) {}

    void finished(const Row& row) {
        ++(row.status == "ok" ? done_ : row.status == "failed" ? failed_ : skipped_);
        if (row.status != "skipped") ++ran_;
        if (quiet_) return;
        const std::size_t remaining = total_ - done_ - failed_ - skipped_;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        char left[64] = "";
        if (ran_ > 0 && remaining > 0 && elapsed / double(ran_) * double(remaining) >= 1.0) std::snprintf(left, sizeof left, ", about %.0f s left", elapsed / double(ran_) * double(remaining));
        if (tty_) {
            std::fprintf(stderr, "\r%zu done, %zu failed, %zu skipped, %zu remaining%s\033[K", done_, failed_, skipped_,
                         remaining, left);
            if (row.status == "failed") std::fprintf(stderr, "\n%s: failed: %s\n", row.input.c_str(), row.message.c_str());
        } else {
            std::fprintf(stderr, "[%zu/%zu] %s: %s%s%s (%.2f s)%s\n", total_ - remaining, total_, row.input.c_str(),
                         row.status.c_str(), row.message.empty() ? "" : ": ", row.message.c_str(), row.seconds, left);
        }
    }
    void end() {
        if (tty_ && !quiet_) std::fprintf(stderr, "\n");
    }

private:
    std::size_t total_, done_ = 0, failed_ = 0, skipped_ = 0, ran_ = 0;
    bool quiet_, tty_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void writeSummary(const std::string& path, const std::vector<Row>& rows) {
    pcskeleton::writeTextFile(path, [&](std::ostream& out) {
        out << kSummaryHeader << '\n';
        for (const Row& row : rows) {
            out << csvField(row.input);
            for (const char* column : {"points", "nodes", "cycles", "tips", "parts", "warnings"}) {
                const auto value = row.values.find(column);
                out << ',' << (value == row.values.end() ? "" : value->second);
            }
            char seconds[32];
            std::snprintf(seconds, sizeof seconds, "%.3f", row.seconds);
            out << ',' << (row.status == "skipped" ? "" : seconds) << ',' << row.status << ',' << csvField(row.message)
                << '\n';
        }
    });
}

// A summary table of an earlier batch may be replaced (a rerun rewrites it); any other file not.
void checkSummaryReplaceable(const std::string& path) {
    if (!pcskeleton::fileExists(path)) return;
    std::ifstream in(path);
    std::string first;
    std::getline(in, first);
    if (first != kSummaryHeader) {
        throw std::runtime_error("--summary '" + path +
                                 "' exists and is not a batch summary table; choose another name (it is left alone)");
    }
}

}  // namespace

std::string childSummaryLine(std::size_t points, int nodes, int cycles, int tips, int parts, std::size_t warnings) {
    return std::string(kChildSummaryMark) + " points=" + std::to_string(points) + " nodes=" + std::to_string(nodes) +
           " cycles=" + std::to_string(cycles) + " tips=" + std::to_string(tips) + " parts=" + std::to_string(parts) +
           " warnings=" + std::to_string(warnings);
}

int runBatch(const std::string& program, const std::vector<BatchInput>& inputs, const BatchSettings& settings) {
    if (!settings.summary.empty()) checkSummaryReplaceable(settings.summary);
    std::vector<Row> rows(inputs.size());
    Progress progress(inputs.size(), settings.quiet);
    std::vector<std::size_t> toRun;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        rows[i].input = inputs[i].path;
        const bool allExist = std::all_of(inputs[i].outputs.begin(), inputs[i].outputs.end(),
                                          [](const auto& output) { return pcskeleton::fileExists(output.second); });
        if (allExist && !settings.force) {
            rows[i].status = "skipped";
            rows[i].message = "its outputs exist already (--force redoes it)";
            progress.finished(rows[i]);
        } else {
            toRun.push_back(i);
        }
    }

    std::vector<std::string> environment = childEnvironment();
    std::vector<Child> running;
    std::size_t next = 0;
    while (next < toRun.size() || !running.empty()) {
        while (next < toRun.size() && int(running.size()) < std::max(1, settings.jobs)) {
            const BatchInput& input = inputs[toRun[next]];
            std::vector<std::string> arguments = {program, input.path};
            for (const auto& [option, file] : input.outputs) arguments.insert(arguments.end(), {option, file});
            arguments.insert(arguments.end(), settings.options.begin(), settings.options.end());
            arguments.insert(arguments.end(), {"--quiet", "--batch-child"});
            if (settings.force) arguments.push_back("--force");
            running.push_back(startChild(program, arguments, environment, toRun[next++]));
        }
        std::vector<pollfd> watched;
        for (const Child& child : running) watched.push_back({child.output, POLLIN, 0});
        if (poll(watched.data(), watched.size(), -1) < 0) {
            if (errno == EINTR) continue;
            throw std::runtime_error(std::string("waiting for the runs failed: ") + std::strerror(errno));
        }
        for (std::size_t c = running.size(); c-- > 0;) {
            if (!(watched[c].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            char buffer[4096];
            const ssize_t got = read(running[c].output, buffer, sizeof buffer);
            if (got > 0) {
                running[c].text.append(buffer, std::size_t(got));
            } else if (got == 0 || errno != EINTR) {
                Row& row = rows[running[c].row];
                finishChild(running[c], row);
                progress.finished(row);
                running.erase(running.begin() + std::ptrdiff_t(c));
            }
        }
    }
    progress.end();
    if (!settings.summary.empty()) writeSummary(settings.summary, rows);

    std::vector<const Row*> failed;
    for (const Row& row : rows) {
        if (row.status == "failed") failed.push_back(&row);
    }
    if (!settings.quiet) {
        std::size_t ok = 0, skipped = 0;
        for (const Row& row : rows) ok += row.status == "ok", skipped += row.status == "skipped";
        std::fprintf(stderr, "pcskeleton: %zu inputs: %zu done, %zu failed, %zu skipped (outputs there already)%s\n",
                     rows.size(), ok, failed.size(), skipped,
                     settings.summary.empty() ? "" : ("; summary in '" + settings.summary + "'").c_str());
    }
    if (failed.empty()) return 0;
    std::fprintf(stderr, "pcskeleton: %zu of %zu inputs failed:\n", failed.size(), rows.size());
    for (const Row* row : failed) std::fprintf(stderr, "  %s: %s\n", row->input.c_str(), row->message.c_str());
    return 1;
}

}  // namespace pcskeleton_cli
