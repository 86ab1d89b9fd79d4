// How much memory a skeleton's computation needs, and its refusal before any work when that
// is more than the machine, the process's limits or the user allow.
#pragma once

#include <cstddef>

namespace pcskeleton {

// Estimated peak memory, in bytes, of the skeleton of `points` points contracting at most
// `maxContractedPoints` of them (0 = all).
double estimatedPeakBytes(std::size_t points, std::size_t maxContractedPoints);

// Throws InvalidInput, naming the memory it needs and what would fit, when that estimate is
// more than `memoryLimit` bytes (0 = no limit of the user's) or than the machine and the
// process's limits allow (machine_memory.h).
void refuseWorkLargerThanMemory(std::size_t points, std::size_t maxContractedPoints, double memoryLimit);

}  // namespace pcskeleton
