// The fork-join pool of the learning kernels.
#include <gtest/gtest.h>

#include <atomic>
#include <new>
#include <thread>
#include <vector>

#include "analysis/parallel.h"

namespace tactile::analysis {
namespace {

TEST(ParallelFor, RunsEveryPartExactlyOnceForAnyThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    for (int parts : {0, 1, 2, 7, 100}) {
      std::vector<std::atomic<int>> runs(static_cast<std::size_t>(parts));
      for (int round = 0; round < 50; ++round)
        parallelFor(parts, threads, [&](int p) { runs[static_cast<std::size_t>(p)]++; });
      for (int p = 0; p < parts; ++p)
        EXPECT_EQ(runs[static_cast<std::size_t>(p)].load(), 50)
            << "part " << p << " of " << parts << ", " << threads << " threads";
    }
  }
}

TEST(ParallelFor, ACallFromInsideAPartRunsOnTheCallingThread) {
  std::atomic<int> inner{0};
  parallelFor(4, 2, [&](int) {
    const std::thread::id outer = std::this_thread::get_id();
    parallelFor(3, 2, [&](int) {
      EXPECT_EQ(std::this_thread::get_id(), outer);
      inner++;
    });
  });
  EXPECT_EQ(inner.load(), 12);
}

TEST(ParallelFor, CallersOnSeveralThreadsAtOnceAllFinish) {
  std::atomic<long> total{0};
  std::vector<std::thread> callers;
  for (int c = 0; c < 4; ++c)
    callers.emplace_back([&] {
      for (int round = 0; round < 200; ++round)
        parallelFor(16, 2, [&](int p) { total += p; });
    });
  for (auto& t : callers)
    t.join();
  EXPECT_EQ(total.load(), 4L * 200 * (15 * 16 / 2));
}

// Two parts that each wait for the other to start run on two threads, so one of them surely runs
// on a pool thread; that one throws. The exception reaches the caller (a pool thread must never let
// it out: that ends the process), and the pool works on afterwards.
TEST(ParallelFor, AnExceptionInAPartOnAPoolThreadReachesTheCaller) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> started{0};
  const auto part = [&](int) {
    ++started;
    while (started.load() < 2)
      std::this_thread::yield();
    if (std::this_thread::get_id() != caller) throw std::bad_alloc();
  };
  EXPECT_THROW(parallelFor(2, 2, part), std::bad_alloc);
  EXPECT_EQ(started.load(), 2);
  std::atomic<int> runs{0};
  parallelFor(8, 2, [&](int) { ++runs; });
  EXPECT_EQ(runs.load(), 8);
}

}  // namespace
}  // namespace tactile::analysis
