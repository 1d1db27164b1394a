// The heap policy `cutaway` and the benchmarks set first (src/app_core/heap_policy.h): memory a batch
// of draws frees is reused by the next without being faulted in again.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "app_core/heap_policy.h"

// AddressSanitizer's allocator ignores mallopt: nothing to test there.
#if !defined(__SANITIZE_ADDRESS__)
namespace {

long minor_faults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

/// llvmpipe's pattern: many 64 KiB blocks (below glibc's mmap threshold: from the heap), written,
/// then all freed. 1024 blocks: 64 MiB, 16,384 pages.
void allocate_write_free() {
    constexpr std::size_t blocks = 1024, block_bytes = 64 * 1024;
    std::vector<void*> kept;
    kept.reserve(blocks);
    for (std::size_t i = 0; i < blocks; ++i) {
        void* block = std::malloc(block_bytes);
        ASSERT_NE(block, nullptr);
        std::memset(block, int(i), block_bytes);
        kept.push_back(block);
    }
    for (void* block : kept) std::free(block);
}

}  // namespace

TEST(HeapPolicy, FreedMemoryIsReusedWithoutPageFaults) {
    ASSERT_TRUE(cutaway::app::keep_freed_heap_memory());
    allocate_write_free();  // the heap grows: its pages are faulted in once
    const long before = minor_faults();
    allocate_write_free();
    // With glibc's default the 64 MiB freed at the top of the heap go back to the system and the
    // second round faults all 16,384 pages in again; kept, it faults none of them (a few hundred
    // allowed for the test's own bookkeeping and gtest).
    EXPECT_LT(minor_faults() - before, 512);
}
#endif
