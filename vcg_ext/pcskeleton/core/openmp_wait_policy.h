// How a program's OpenMP threads wait at the end of a parallel loop.
//
// libgomp spins for a while before it sleeps (OMP_WAIT_POLICY unset). When other programs
// keep the cores busy, a spinning thread takes the time its partner needs to finish, and
// every one of the reconstruction solver's parallel loops ends late (docs/benchmarks.md#measurements-behind-the-constants).
// libgomp reads the policy once, when it is loaded, before main():
// a program can choose it for itself only by starting again with the variable set.
#pragma once

#include <cstdlib>
#include <unistd.h>

namespace pcskeleton {

// Restarts the running program with OMP_WAIT_POLICY=passive unless the user chose a wait
// policy or spin count. Call it first thing in main(). Returns only when nothing was to
// be done or the restart failed (then the program goes on as it is).
inline void restartWithPassiveOpenMpWaits(char** argv) {
    if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
    if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
    execv("/proc/self/exe", argv);
}

}  // namespace pcskeleton
