#include "linalg/FreedMemoryReuse.hpp"

#include <atomic>
#include <climits>
#include <mutex>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mcdda {

namespace {
std::atomic<int> holders{0};
std::once_flag parameters_set;
}  // namespace

void reuse_freed_memory() {
    std::call_once(parameters_set, [] {
#if defined(__GLIBC__)
        // glibc still maps a block where the heap cannot grow. Each of these settings alone
        // leaves the faults: a mapped block is unmapped when freed, a trimmed top is returned,
        // and a thread's arena maps what does not fit its 64 MB heaps.
        mallopt(M_MMAP_MAX, 0);
        mallopt(M_TRIM_THRESHOLD, INT_MAX);
        mallopt(M_ARENA_MAX, 1);
#endif
    });
}

FreedMemoryReuse::FreedMemoryReuse() {
    reuse_freed_memory();
    ++holders;
}

FreedMemoryReuse::~FreedMemoryReuse() {
#if defined(__GLIBC__)
    if (--holders == 0) malloc_trim(0);
#else
    --holders;
#endif
}

}  // namespace mcdda
