// Runs one benchmark case in a child process, so that its peak resident memory is its
// own and a crash or an out-of-memory kill fails only that row.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <type_traits>

// `measure` returns a trivially copyable row; false if the child failed.
template <class Row, class Measure>
bool runInChild(Measure measure, Row& row, double& peakMegabytes) {
    static_assert(std::is_trivially_copyable<Row>::value, "the row crosses a pipe");
    std::fflush(stdout);  // or the child would print the buffered lines again
    int channel[2];
    if (pipe(channel) != 0) return false;
    const pid_t child = fork();
    if (child == 0) {
        close(channel[0]);
        const Row result = measure();
        _exit(write(channel[1], &result, sizeof result) == sizeof result ? 0 : 1);
    }
    close(channel[1]);
    const bool received = read(channel[0], &row, sizeof row) == sizeof row;
    close(channel[0]);
    int status = 0;
    struct rusage usage {};
    wait4(child, &status, 0, &usage);
    peakMegabytes = usage.ru_maxrss / 1024.0;
    return received && status == 0;
}
