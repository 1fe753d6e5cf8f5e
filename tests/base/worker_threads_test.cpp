// Worker threads that report instead of ending the process (base/worker_threads.h).
#include <gtest/gtest.h>

#include <atomic>
#include <new>
#include <stdexcept>
#include <thread>

#include "base/worker_threads.h"

namespace tactile {
namespace {

// Every worker waits until all have started, so each one surely runs; then only the workers that
// are not the calling thread throw.
TEST(RunWorkers, AnExceptionInAWorkerThreadReachesTheCaller) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> started{0};
  std::atomic<int> finished{0};
  const auto work = [&] {
    ++started;
    while (started.load() < 3)
      std::this_thread::yield();
    if (std::this_thread::get_id() != caller) throw std::bad_alloc();
    ++finished;
  };
  EXPECT_THROW(runWorkers(3, work), std::bad_alloc);
  EXPECT_EQ(started.load(), 3);
  EXPECT_EQ(finished.load(), 1);  // the calling thread's share ran to its end
}

TEST(RunWorkers, AnExceptionOnTheCallingThreadWaitsForTheOthers) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> started{0};
  std::atomic<int> finished{0};
  const auto work = [&] {
    ++started;
    while (started.load() < 2)
      std::this_thread::yield();
    if (std::this_thread::get_id() == caller) throw std::runtime_error("caller failed");
    ++finished;
  };
  try {
    runWorkers(2, work);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "caller failed");
  }
  // The other worker was joined before the exception left runWorkers.
  EXPECT_EQ(finished.load(), 1);
}

TEST(RunWorkers, OneThreadRunsOnTheCaller) {
  const std::thread::id caller = std::this_thread::get_id();
  int runs = 0;
  runWorkers(1, [&] {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    ++runs;
  });
  EXPECT_EQ(runs, 1);
  EXPECT_THROW(runWorkers(0, [] { throw std::runtime_error("x"); }), std::runtime_error);
}

TEST(RunWorkers, FailedTellsTheOthersToStop) {
  FirstException failure;
  std::atomic<int> started{0};
  std::atomic<bool> sawFailure{false};
  const std::thread::id caller = std::this_thread::get_id();
  const auto work = [&] {
    ++started;
    while (started.load() < 2)
      std::this_thread::yield();
    if (std::this_thread::get_id() != caller) throw std::runtime_error("worker failed");
    while (!failure.failed())
      std::this_thread::yield();
    sawFailure = true;
  };
  EXPECT_THROW(runWorkers(2, work, &failure), std::runtime_error);
  EXPECT_TRUE(sawFailure.load());
}

}  // namespace
}  // namespace tactile
