// parallel_for: every index exactly once, on more than one thread when asked, exceptions carried
// to the caller, a loop inside a loop run serially.
#include "parallel/ParallelFor.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace mcdda {
namespace {

/// Sets the thread count for one test and puts the default back.
struct Threads {
    explicit Threads(int n) { set_thread_count(n); }
    ~Threads() { set_thread_count(0); }
};

TEST(ParallelFor, CoversEveryIndexOnceInContiguousRanges) {
    for (int threads : {1, 2, 3, 7}) {
        Threads use(threads);
        for (int count : {1, 2, 5, 1000, 8191}) {
            std::vector<int> hits(count, 0);
            std::atomic<int> ranges{0};
            parallel_for(count, [&](int begin, int end) {
                ASSERT_LT(begin, end);
                ++ranges;
                for (int i = begin; i < end; ++i) ++hits[i];
            });
            for (int i = 0; i < count; ++i) ASSERT_EQ(hits[i], 1) << "index " << i << " of " << count;
            EXPECT_LE(ranges, std::min(threads, count));
        }
    }
}

TEST(ParallelFor, UsesTheThreadsItIsGiven) {
    Threads use(2);
    std::mutex m;
    std::set<std::thread::id> seen;
    parallel_for(2, [&](int, int) {
        std::lock_guard<std::mutex> lock(m);
        seen.insert(std::this_thread::get_id());
    });
    EXPECT_EQ(seen.size(), 2u);
    EXPECT_EQ(thread_count(), 2);
}

TEST(ParallelFor, AnExceptionInABodyReachesTheCaller) {
    Threads use(2);
    EXPECT_THROW(parallel_for(100,
                              [&](int begin, int) {
                                  if (begin > 0) throw std::runtime_error("worker failed");
                              }),
                 std::runtime_error);
    // The pool still works afterwards.
    std::atomic<int> sum{0};
    parallel_for(100, [&](int begin, int end) { sum += end - begin; });
    EXPECT_EQ(sum, 100);
}

TEST(ParallelFor, ALoopInsideALoopRunsSerially) {
    Threads use(2);
    std::atomic<int> total{0};
    parallel_for(4, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) parallel_for(10, [&](int b, int e) { total += e - b; });
    });
    EXPECT_EQ(total, 40);
}

}  // namespace
}  // namespace mcdda
