// The one place that starts threads. Every parallel loop of the project goes through parallelFor
// (or, for kernels whose parts take microseconds, pooledParallelFor), so that a worker's exception
// (std::bad_alloc under memory pressure above all) is caught on the worker, every worker is joined,
// and the first exception is thrown again on the calling thread, where the same error path as a
// one-thread run reports it. No worker ever ends the process through std::terminate.
#pragma once

#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace tactile {

// The most threads a parallel loop starts, whatever was asked for.
inline constexpr unsigned kMaxWorkerThreads = 256;

// Threads for `items` independent items: `requested`, or one per hardware thread when it is 0;
// never more than kMaxWorkerThreads nor more than the items, never fewer than 1.
unsigned workerThreadCount(unsigned requested, std::size_t items);

// The first exception of several threads, kept until the caller throws it again.
class FirstException {
 public:
  // Runs f() and keeps its exception, if any (the first one kept wins); true when f() returned.
  template <class F>
  bool capture(F&& f) noexcept {
    try {
      f();
      return true;
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!first_) first_ = std::current_exception();
      failed_.store(true, std::memory_order_release);
      return false;
    }
  }
  // True once any capture() has caught an exception: workers may stop taking new work.
  bool failed() const { return failed_.load(std::memory_order_acquire); }
  // Throws the kept exception on the calling thread, if there is one (again on every call).
  void rethrow() {
    std::exception_ptr e;
    {
      std::lock_guard lock(mutex_);
      e = first_;
    }
    if (e) std::rethrow_exception(e);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr first_;
  std::atomic<bool> failed_{false};
};

// Threads that run work() beside the calling thread, which goes on with its own part (a writer
// taking what the workers produce, say). An exception in work() lands in `failure` (the thread
// then ends); join() (and the destructor) waits for every thread. Neither copyable nor movable:
// the threads run this object's work.
class BackgroundWorkers {
 public:
  // Starts `threads` threads. Starting a thread can fail (std::system_error): that too lands in
  // `failure`, and the threads already started run on.
  BackgroundWorkers(unsigned threads, std::function<void()> work, FirstException& failure);
  BackgroundWorkers(const BackgroundWorkers&) = delete;
  BackgroundWorkers& operator=(const BackgroundWorkers&) = delete;
  ~BackgroundWorkers() { join(); }

  // Waits for every thread to return; again on every call.
  void join();

 private:
  std::function<void()> work_;
  std::vector<std::thread> threads_;
};

namespace detail {
bool parallelForIndices(std::size_t count, unsigned threads,
                        const std::function<bool(std::size_t)>& body);
}  // namespace detail

// Runs body(i) for every i in [0, count) on workerThreadCount(threads, count) threads, the calling
// thread being one of them (one thread: only the calling thread), and returns when every thread
// has returned. Indices are handed out one at a time in increasing order, so callers that want
// the big items first hand out a sorted order (body(i) works on order[i]), and results are
// deterministic when body(i) writes only the i-th output.
//
// Cancellation: a body that returns false (a bool body; a void body never stops) stops the
// handing out of further indices; bodies already running finish. An exception in a body does the
// same, and after every thread has been joined the first exception is thrown again here.
// Returns true when every index ran and no body returned false.
template <class Body>
bool parallelFor(std::size_t count, unsigned threads, Body&& body) {
  if constexpr (std::is_void_v<std::invoke_result_t<Body&, std::size_t>>) {
    return detail::parallelForIndices(count, threads, [&body](std::size_t i) {
      body(i);
      return true;
    });
  } else {
    return detail::parallelForIndices(
        count, threads, [&body](std::size_t i) { return static_cast<bool>(body(i)); });
  }
}

// The same contract for kernels whose parts take microseconds (EM and k-means passes), where
// starting threads would cost more than the work: up to `threads` threads of a pool that persists
// between calls (one thread fewer than the hardware has, besides the caller). Parts are handed out
// dynamically, so each part's result must not depend on the thread that ran it. A call made while
// another call is using the pool, or from inside a part, runs its parts on the calling thread.
void pooledParallelFor(int parts, int threads, const std::function<void(int)>& f);

}  // namespace tactile
