// The parallel loops every part uses (base/parallel.h): each index once, a worker's exception on
// the caller, cancellation, and the persistent pool of the learning kernels.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <new>
#include <stdexcept>
#include <thread>
#include <vector>

#include "base/parallel.h"

namespace tactile {
namespace {

TEST(WorkerThreadCount, NeverMoreThanTheItemsNorFewerThanOne) {
  EXPECT_EQ(workerThreadCount(4, 10), 4u);
  EXPECT_EQ(workerThreadCount(8, 3), 3u);
  EXPECT_EQ(workerThreadCount(8, 0), 1u);
  EXPECT_EQ(workerThreadCount(1000, 100000), kMaxWorkerThreads);
  EXPECT_GE(workerThreadCount(0, 100000), 1u);  // one per hardware thread
  EXPECT_EQ(workerThreadCount(0, 1), 1u);
}

TEST(ParallelFor, RunsEveryIndexExactlyOnceForAnyThreadCount) {
  for (unsigned threads : {0u, 1u, 2u, 3u, 8u}) {
    for (std::size_t count : {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{100}}) {
      std::vector<std::atomic<int>> runs(count);
      EXPECT_TRUE(parallelFor(count, threads, [&](std::size_t i) { runs[i]++; }));
      for (std::size_t i = 0; i < count; ++i)
        EXPECT_EQ(runs[i].load(), 1) << "index " << i << " of " << count << ", " << threads;
    }
  }
}

TEST(ParallelFor, AnEmptyRangeCallsNothing) {
  int calls = 0;
  EXPECT_TRUE(parallelFor(0, 4, [&](std::size_t) { ++calls; }));
  EXPECT_EQ(calls, 0);
}

// Asking for more threads than items starts no thread that would find nothing to do: one item
// runs on the calling thread.
TEST(ParallelFor, MoreThreadsThanItems) {
  const std::thread::id caller = std::this_thread::get_id();
  std::thread::id ran;
  EXPECT_TRUE(parallelFor(1, 16, [&](std::size_t) { ran = std::this_thread::get_id(); }));
  EXPECT_EQ(ran, caller);
  std::vector<int> out(3, 0);
  EXPECT_TRUE(parallelFor(3, 64, [&](std::size_t i) { out[i] = static_cast<int>(i) * 2; }));
  EXPECT_EQ(out, (std::vector<int>{0, 2, 4}));
}

TEST(ParallelFor, OneThreadRunsOnTheCallerInOrder) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::size_t> order;
  parallelFor(5, 1, [&](std::size_t i) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    order.push_back(i);
  });
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
}

// Results written by index are the same whatever the thread count.
TEST(ParallelFor, ResultsByIndexDoNotDependOnTheThreads) {
  const auto squares = [](unsigned threads) {
    std::vector<long> out(500);
    parallelFor(out.size(), threads,
                [&](std::size_t i) { out[i] = static_cast<long>(i) * static_cast<long>(i); });
    return out;
  };
  const std::vector<long> one = squares(1);
  EXPECT_EQ(squares(2), one);
  EXPECT_EQ(squares(7), one);
}

TEST(ParallelFor, ABodyReturningFalseStopsTheHandingOut) {
  for (unsigned threads : {1u, 2u, 4u}) {
    std::atomic<std::size_t> ran{0};
    std::atomic<bool> cancelled{false};
    const bool all = parallelFor(10000, threads, [&](std::size_t i) {
      ++ran;
      if (i == 10) {
        cancelled = true;
        return false;
      }
      // Later indices wait for the cancel, so none can run far ahead of it.
      while (i > 10 && !cancelled.load())
        std::this_thread::yield();
      return true;
    });
    EXPECT_FALSE(all);
    EXPECT_GE(ran.load(), 11u);  // every index before the cancel ran
    EXPECT_LT(ran.load(), 1000u);
  }
  EXPECT_FALSE(parallelFor(1, 1, [](std::size_t) { return false; }));
  EXPECT_TRUE(parallelFor(3, 2, [](std::size_t) { return true; }));
}

// Every thread waits until all have started, so each one surely runs; then only the threads that
// are not the calling thread throw.
TEST(ParallelFor, AnExceptionInAWorkerThreadReachesTheCaller) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> started{0};
  std::atomic<int> finished{0};
  const auto body = [&](std::size_t) {
    ++started;
    while (started.load() < 3)
      std::this_thread::yield();
    if (std::this_thread::get_id() != caller) throw std::bad_alloc();
    ++finished;
  };
  EXPECT_THROW(parallelFor(3, 3, body), std::bad_alloc);
  EXPECT_EQ(started.load(), 3);
  EXPECT_EQ(finished.load(), 1);  // the calling thread's item ran to its end
}

TEST(ParallelFor, AnExceptionOnTheCallingThreadWaitsForTheOthers) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> started{0};
  std::atomic<int> finished{0};
  const auto body = [&](std::size_t) {
    ++started;
    while (started.load() < 2)
      std::this_thread::yield();
    if (std::this_thread::get_id() == caller) throw std::runtime_error("caller failed");
    ++finished;
  };
  try {
    parallelFor(2, 2, body);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "caller failed");
  }
  // The other thread was joined before the exception left parallelFor.
  EXPECT_EQ(finished.load(), 1);
}

TEST(ParallelFor, AnExceptionStopsTheHandingOut) {
  std::atomic<std::size_t> ran{0};
  std::atomic<bool> thrown{false};
  const auto body = [&](std::size_t i) {
    ++ran;
    if (i == 5) {
      thrown = true;
      throw std::runtime_error("item 5");
    }
    while (i > 5 && !thrown.load())
      std::this_thread::yield();
    // Items after the throw take a while, as real work does: while the thrower's stack unwinds
    // (which a loaded machine can stretch to milliseconds), a few more are handed out, never a
    // run through the rest (items that cost nothing went through thousands).
    if (i > 5) std::this_thread::sleep_for(std::chrono::microseconds(200));
  };
  EXPECT_THROW(parallelFor(10000, 2, body), std::runtime_error);
  EXPECT_GE(ran.load(), 6u);
  EXPECT_LT(ran.load(), 1000u);
  EXPECT_THROW(parallelFor(1, 1, [](std::size_t) { throw std::runtime_error("x"); }),
               std::runtime_error);
}

TEST(BackgroundWorkers, RunBesideTheCallerAndKeepTheFirstException) {
  FirstException failure;
  std::atomic<int> ran{0};
  {
    BackgroundWorkers workers(
        3, [&] { ++ran; }, failure);
    workers.join();
    EXPECT_EQ(ran.load(), 3);
  }
  EXPECT_FALSE(failure.failed());
  {
    BackgroundWorkers workers(
        2, [] { throw std::runtime_error("worker failed"); }, failure);
  }  // joined here
  EXPECT_TRUE(failure.failed());
  EXPECT_THROW(failure.rethrow(), std::runtime_error);
}

TEST(PooledParallelFor, RunsEveryPartExactlyOnceForAnyThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    for (int parts : {0, 1, 2, 7, 100}) {
      std::vector<std::atomic<int>> runs(static_cast<std::size_t>(parts));
      for (int round = 0; round < 50; ++round)
        pooledParallelFor(parts, threads, [&](int p) { runs[static_cast<std::size_t>(p)]++; });
      for (int p = 0; p < parts; ++p)
        EXPECT_EQ(runs[static_cast<std::size_t>(p)].load(), 50)
            << "part " << p << " of " << parts << ", " << threads << " threads";
    }
  }
}

TEST(PooledParallelFor, ACallFromInsideAPartRunsOnTheCallingThread) {
  std::atomic<int> inner{0};
  pooledParallelFor(4, 2, [&](int) {
    const std::thread::id outer = std::this_thread::get_id();
    pooledParallelFor(3, 2, [&](int) {
      EXPECT_EQ(std::this_thread::get_id(), outer);
      inner++;
    });
  });
  EXPECT_EQ(inner.load(), 12);
}

TEST(PooledParallelFor, CallersOnSeveralThreadsAtOnceAllFinish) {
  std::atomic<long> total{0};
  parallelFor(4, 4, [&](std::size_t) {
    for (int round = 0; round < 200; ++round)
      pooledParallelFor(16, 2, [&](int p) { total += p; });
  });
  EXPECT_EQ(total.load(), 4L * 200 * (15 * 16 / 2));
}

// Two parts that each wait for the other to start run on two threads, so one of them surely runs
// on a pool thread; that one throws. The exception reaches the caller (a pool thread must never let
// it out: that ends the process), and the pool works on afterwards.
TEST(PooledParallelFor, AnExceptionInAPartOnAPoolThreadReachesTheCaller) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> started{0};
  const auto part = [&](int) {
    ++started;
    while (started.load() < 2)
      std::this_thread::yield();
    if (std::this_thread::get_id() != caller) throw std::bad_alloc();
  };
  EXPECT_THROW(pooledParallelFor(2, 2, part), std::bad_alloc);
  EXPECT_EQ(started.load(), 2);
  std::atomic<int> runs{0};
  pooledParallelFor(8, 2, [&](int) { ++runs; });
  EXPECT_EQ(runs.load(), 8);
}

}  // namespace
}  // namespace tactile
