#include "pcskeleton/contraction/contraction_memory.h"

#include "pcskeleton/core/errors.h"
#include "pcskeleton/internal/machine_memory.h"

#include <algorithm>
#include <sstream>
#include <string>

namespace pcskeleton {

namespace {

// Peak memory per point, as bench_skeleton measures it (docs/benchmarks.md): a contracted
// point holds its 1-ring, Laplacian rows and factor; a point only carried holds the input,
// the outlier test's neighbour lists and k-d tree, its subsample link, its contracted
// position and node.
constexpr double kBytesPerContractedPoint = 2700;
constexpr double kBytesPerCarriedPoint = 135;
// Fewer contracted points than this leave too few per node to be worth suggesting.
constexpr std::size_t kFewestUsefulContractedPoints = 2000;

}  // namespace

double estimatedPeakBytes(std::size_t points, std::size_t maxContractedPoints) {
    const std::size_t contracted = maxContractedPoints == 0 ? points : std::min(points, maxContractedPoints);
    return kBytesPerContractedPoint * double(contracted) + kBytesPerCarriedPoint * double(points - contracted);
}

void refuseWorkLargerThanMemory(std::size_t points, std::size_t maxContractedPoints, double memoryLimit) {
    const double needed = estimatedPeakBytes(points, maxContractedPoints);
    const MemoryAllowance allowance = usableMemory();
    const bool userLimit = memoryLimit > 0 && !(allowance.bytes > 0 && allowance.bytes < memoryLimit);
    const double limit = userLimit ? memoryLimit : allowance.bytes;
    if (!(limit > 0) || needed <= limit) return;
    std::ostringstream text;
    text.precision(2);
    text << "A skeleton of " << points << " points, " << (maxContractedPoints == 0 ? "all" : "at most")
         << " " << (maxContractedPoints == 0 ? points : std::min(points, maxContractedPoints))
         << " of them contracted, needs about " << needed / 1e9 << " GB of memory, more than the "
         << limit / 1e9 << " GB " << (userLimit ? std::string("allowed") : std::string("that ") + allowance.limit + " leaves");
    // The most contracted points that would fit, every other point only carried.
    const double fitting = (limit - kBytesPerCarriedPoint * double(points)) / (kBytesPerContractedPoint - kBytesPerCarriedPoint);
    if (fitting >= double(kFewestUsefulContractedPoints)) {
        text << "; at most " << std::size_t(fitting) << " contracted points would fit";
        throw InvalidInput(text.str() + ".", {Remedy::lower(Parameter::ContractedPoints)});
    }
    throw InvalidInput(text.str() + ": split the scan, or use a machine with more memory.");
}

}  // namespace pcskeleton
