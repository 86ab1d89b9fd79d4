// Runs benchmark cases in child processes, so that each case's peak resident memory is its
// own and a crash or an out-of-memory kill fails only that row. A case can be started before
// the one ahead of it is finished, so that several run at a time.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <type_traits>

// A case running in a child: its process and the pipe its row comes back through.
struct ChildCase {
    pid_t pid = -1;
    int channel = -1;
};

// Starts `measure`, which returns a trivially copyable row, in a child.
template <class Row, class Measure>
ChildCase startInChild(Measure measure) {
    static_assert(std::is_trivially_copyable<Row>::value, "the row crosses a pipe");
    std::fflush(stdout);  // or the child would print the buffered lines again
    int channel[2];
    if (pipe(channel) != 0) return {};
    const pid_t child = fork();
    if (child == 0) {
        close(channel[0]);
        const Row result = measure();
        _exit(write(channel[1], &result, sizeof result) == sizeof result ? 0 : 1);
    }
    close(channel[1]);
    if (child < 0) {
        close(channel[0]);
        return {};
    }
    return {child, channel[0]};
}

// Waits for a started case's row; false if it could not start or the child failed.
template <class Row>
bool finishInChild(const ChildCase& started, Row& row, double& peakMegabytes) {
    if (started.pid < 0) return false;
    // The row is smaller than a pipe's atomic write: it arrives whole or not at all.
    const bool received = read(started.channel, &row, sizeof row) == sizeof row;
    close(started.channel);
    int status = 0;
    struct rusage usage {};
    wait4(started.pid, &status, 0, &usage);
    peakMegabytes = usage.ru_maxrss / 1024.0;
    return received && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// One case, start to finish.
template <class Row, class Measure>
bool runInChild(Measure measure, Row& row, double& peakMegabytes) {
    return finishInChild(startInChild<Row>(measure), row, peakMegabytes);
}
