#include "pcskeleton/internal/machine_memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace pcskeleton {

namespace {

// The first number of a file (a control group's, /proc/self/statm); 0 for "max", a
// missing file or anything else.
double firstNumberIn(const std::string& path) {
    std::ifstream in(path);
    unsigned long long value = 0;
    if (!(in >> value)) return 0.0;
    return double(value);
}

// The process's control-group folders: "0::/path" (v2) and "N:memory:/path" (v1) in
// /proc/self/cgroup, mounted under /sys/fs/cgroup.
struct CgroupMemory {
    double limit = 0, used = 0;
};

CgroupMemory cgroupMemory() {
    std::ifstream in("/proc/self/cgroup");
    CgroupMemory memory;
    for (std::string line; std::getline(in, line);) {
        const auto first = line.find(':'), second = line.find(':', first + 1);
        if (first == std::string::npos || second == std::string::npos) continue;
        const std::string controllers = line.substr(first + 1, second - first - 1);
        const std::string path = line.substr(second + 1);
        double limit = 0, used = 0;
        if (controllers.empty()) {
            limit = firstNumberIn("/sys/fs/cgroup" + path + "/memory.max");
            used = firstNumberIn("/sys/fs/cgroup" + path + "/memory.current");
        } else if (("," + controllers + ",").find(",memory,") != std::string::npos) {
            limit = firstNumberIn("/sys/fs/cgroup/memory" + path + "/memory.limit_in_bytes");
            used = firstNumberIn("/sys/fs/cgroup/memory" + path + "/memory.usage_in_bytes");
            if (limit >= 1e18) limit = 0;  // v1 writes "no limit" as a huge number
        }
        if (limit > 0 && (memory.limit == 0 || limit - used < memory.limit - memory.used)) memory = {limit, used};
    }
    return memory;
}

// The address space the process maps now (VmSize), in bytes.
double mappedBytes() { return firstNumberIn("/proc/self/statm") * double(sysconf(_SC_PAGE_SIZE)); }

}  // namespace

double physicalMemoryBytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
}

MemoryAllowance usableMemory() {
    MemoryAllowance allowance{kUsableShareOfMemory * physicalMemoryBytes(), "this machine"};
    const auto consider = [&](double bytes, const char* limit) {
        if (allowance.bytes == 0 || bytes < allowance.bytes) allowance = {bytes > 0 ? bytes : 1.0, limit};
    };
    rlimit addressSpace{};
    if (getrlimit(RLIMIT_AS, &addressSpace) == 0 && addressSpace.rlim_cur != RLIM_INFINITY) {
        consider(double(addressSpace.rlim_cur) - mappedBytes(), "the process's address-space limit (ulimit -v)");
    }
    const CgroupMemory cgroup = cgroupMemory();
    if (cgroup.limit > 0) consider(cgroup.limit - cgroup.used, "its control group's memory limit");
    return allowance;
}

}  // namespace pcskeleton
