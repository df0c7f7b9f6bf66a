// FreedMemoryReuse: a large block comes from the heap, stays there once freed (the next
// factorisation reuses its pages without faulting them in again), and is returned to the system
// when the last holder goes.
#include "linalg/FreedMemoryReuse.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mcdda {
namespace {

TEST(FreedMemoryReuse, ALargeBlockIsKeptInTheHeapUntilTheLastHolderGoes) {
#if !defined(__GLIBC__) || defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "the malloc parameters are glibc's (a sanitizer brings its own malloc)";
#else
    constexpr std::size_t size = std::size_t{256} << 20;  // above glibc's largest mmap threshold
    {
        FreedMemoryReuse holder;
        const std::size_t mapped_before = mallinfo2().hblks;
        char* volatile block = static_cast<char*>(std::malloc(size));
        ASSERT_NE(block, nullptr);
        std::memset(block, 1, size);
        EXPECT_EQ(mallinfo2().hblks, mapped_before) << "the block was mapped on its own: freeing it unmaps it";
        std::free(block);
        EXPECT_GE(mallinfo2().fordblks, size) << "the freed block left the heap";
    }
    EXPECT_LT(mallinfo2().keepcost, size) << "the free top of the heap was kept after the last holder went";
#endif
}

}  // namespace
}  // namespace mcdda
