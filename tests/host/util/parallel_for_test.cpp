// parallel_for: every index exactly once whatever the thread count, failures surface after all work is done.
#include "host/util/parallel_for.hpp"

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace driftlab::host {
namespace {

TEST(ParallelFor, CallsEveryIndexExactlyOnceWhateverTheThreadCount) {
    for (int threads : {-1, 0, 1, 2, 3, 8}) {
        for (std::size_t count : {0u, 1u, 2u, 7u, 100u}) {
            std::vector<std::atomic<int>> calls(count);
            parallel_for(count, threads, [&](std::size_t i) { ++calls[i]; });
            for (std::size_t i = 0; i < count; ++i)
                EXPECT_EQ(calls[i], 1) << "index " << i << " of " << count << ", threads " << threads;
        }
    }
}

TEST(ParallelFor, RunsOnAsManyThreadsAsAskedWhenThereIsWork) {
    // Each call waits until `threads` calls are under way at once, which happens only if the pool has that many
    // threads; a pool with fewer would wait forever, so the wait gives up after a generous while and the count fails.
    constexpr int kThreads = 3;
    std::atomic<int> running{0}, most{0};
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    parallel_for(kThreads, kThreads, [&](std::size_t) {
        const int now = ++running;
        for (int seen = most.load(); now > seen && !most.compare_exchange_weak(seen, now);) {
        }
        while (most.load() < kThreads && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
    });
    EXPECT_EQ(most.load(), kThreads);
}

TEST(ParallelFor, RethrowsTheFailureAfterTheOtherIndicesRan) {
    std::atomic<int> done{0};
    EXPECT_THROW(parallel_for(50, 2,
                              [&](std::size_t i) {
                                  if (i == 3) throw std::runtime_error("index 3");
                                  ++done;
                              }),
                 std::runtime_error);
    EXPECT_EQ(done.load(), 49);
}

}  // namespace
}  // namespace driftlab::host
