// How a program's OpenMP threads wait at the end of a parallel loop.
//
// libgomp spins for a while before it sleeps (OMP_WAIT_POLICY unset). When other programs
// keep the cores busy, a spinning thread takes the time its partner needs to finish, and
// every one of the reconstruction solver's parallel loops ends late: `bench_reconstruction
// 128` beside two busy loops on 2 cores solved the torus in 4.4 s and the cube frame in
// 10.1 s with spinning waits, 2.2 s and 6.9 s with passive ones (1.3 s and 3.8 s on an idle
// machine, either way). libgomp reads the policy once, when it is loaded, before main():
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
