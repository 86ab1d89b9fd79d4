// How much memory work may use, for the refusals of work that would not fit (the skeleton
// of a huge cloud, the reconstruction's grid): refusing beats being killed by the kernel,
// or running out of memory, half-way.
#pragma once

namespace pcskeleton {

// Work may use up to this share of the physical memory: the rest is the system's and the
// front end's (MeshLab holds the layers too).
inline constexpr double kUsableShareOfMemory = 0.8;

// Physical memory in bytes; 0 if unknown.
double physicalMemoryBytes();

struct MemoryAllowance {
    double bytes = 0;          // what work may still allocate; 0 if unknown
    const char* limit = "";    // what sets it: "this machine", "the process's address-space limit (ulimit -v)", ...
};

// The least of: kUsableShareOfMemory of the physical memory; what the process's
// address-space limit (RLIMIT_AS) leaves beyond its current size; what its control
// group's memory limit (cgroup v2 memory.max or v1 memory.limit_in_bytes) leaves beyond
// its current use.
MemoryAllowance usableMemory();

}  // namespace pcskeleton
