// The robustness suite's cases: shapes whose answer is known (tubes along known curves,
// real models from Debian's libcgal-demo) and the conditions real scans put them in
// (noise, outliers, uneven density, virtual scans, misaligned scans). Shared by the
// benchmarks of the skeleton (bench_robustness) and of the surface (bench_surface).
#pragma once

#include <pcskeleton/core/point.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pcskeleton::bench {

constexpr int kUnknown = -1;

// A shape to skeletonise: how to sample it, and what is known about its skeleton.
struct Subject {
    std::string name;
    int cycles = kUnknown, tips = kUnknown;
    int components = 1;
    // Chosen on the tuning half (false) only; the held-out half (true) tells whether a choice
    // generalises.
    bool heldOut = false;
    double area = 0.0;
    std::function<PointList(std::size_t n, std::uint32_t seed)> sample;
    std::function<bool(const Point&)> inside;             // empty: not known
    std::function<double(const Point&)> centreDistance;   // empty: no known centre curve
    std::function<double(const Point&)> surfaceDistance;  // to the true surface; empty: not known
    PointList ends;                                       // where the shape ends, tip by tip
};

struct Condition {
    const char* name;
    std::function<PointList(const Subject&, std::size_t n, std::uint32_t seed)> make;
};

// The tube and sheet shapes, then the libcgal-demo models (each skipped, with a line on stdout, when
// libcgal-demo is not installed).
std::vector<Subject> robustnessSubjects();

// Clean; noise 0.5/1/2%; outliers 1/5%; half in 10%; scans from 1 view (three directions)
// and 4 views; five scans misaligned by 0.5/1%.
std::vector<Condition> conditions();

}  // namespace pcskeleton::bench
