// The memory work may use: a share of this machine's memory, and less under the process's
// address-space limit (ulimit -v), which a child process sets for itself here.
#include <pcskeleton/internal/machine_memory.h>

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>

using namespace pcskeleton;

TEST(MachineMemory, ThisMachineHasMemoryAndWorkMayUseAShareOfIt) {
    const double physical = physicalMemoryBytes();
    ASSERT_GT(physical, 64e6);
    const MemoryAllowance allowance = usableMemory();
    EXPECT_GT(allowance.bytes, 0.0);
    EXPECT_LE(allowance.bytes, kUsableShareOfMemory * physical * (1 + 1e-12));
    EXPECT_GT(std::strlen(allowance.limit), 0u);
}

#if !defined(__SANITIZE_ADDRESS__)
TEST(MachineMemory, TheAddressSpaceLimitIsWhatItLeaves) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        rlimit current{};
        getrlimit(RLIMIT_AS, &current);
        const rlim_t cap = 3ull << 30;  // 3 GB, more than this test's own size
        rlimit limited{cap, current.rlim_max};
        if (setrlimit(RLIMIT_AS, &limited) != 0) _exit(2);
        const MemoryAllowance allowance = usableMemory();
        const bool underCap = allowance.bytes > 0 && allowance.bytes < double(cap);
        const bool named = std::strstr(allowance.limit, "ulimit -v") != nullptr;
        _exit(underCap && named ? 0 : 1);
    }
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: the allowance ignored the limit; 2: the limit could not be set";
}
#endif
