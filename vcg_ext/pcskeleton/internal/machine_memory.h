// How much memory this machine has, for the refusals of work that would not fit (the
// skeleton of a huge cloud, the reconstruction's grid): refusing beats being killed by
// the kernel half-way.
#pragma once

#include <unistd.h>

namespace pcskeleton {

// Work may use up to this share of the physical memory: the rest is the system's and the
// front end's (MeshLab holds the layers too).
inline constexpr double kUsableShareOfMemory = 0.8;

// Physical memory in bytes; 0 if unknown.
inline double physicalMemoryBytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
}

}  // namespace pcskeleton
