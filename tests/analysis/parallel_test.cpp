// The fork-join pool of the learning kernels.
#include <gtest/gtest.h>

#include <atomic>
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

}  // namespace
}  // namespace tactile::analysis
