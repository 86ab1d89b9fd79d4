// Progress reporting shared by the long-running steps.
#pragma once

#include <functional>

namespace pcskeleton {

// Called with a percentage (0..100) of the current step and a short description.
// Always called from the thread that started the computation, so a GUI may repaint.
using ProgressCallback = std::function<void(int percent, const char* what)>;

inline void report(const ProgressCallback& progress, int percent, const char* what) {
    if (progress) progress(percent, what);
}

// A callback for a sub-step that maps its 0..100 onto [from, to] of `progress`.
inline ProgressCallback progressRange(const ProgressCallback& progress, int from, int to) {
    if (!progress) return {};
    return [progress, from, to](int percent, const char* what) { progress(from + (to - from) * percent / 100, what); };
}

}  // namespace pcskeleton
