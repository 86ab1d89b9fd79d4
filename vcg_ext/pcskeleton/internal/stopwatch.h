// Wall-clock time of a stage, for the reports' "time:" lines.
#pragma once

#include <chrono>

namespace pcskeleton {

class Stopwatch {
public:
    Stopwatch() : start_(Clock::now()) {}
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    void restart() { start_ = Clock::now(); }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_;
};

}  // namespace pcskeleton
