// Worker threads that never take the process down: an exception thrown in any worker
// (std::bad_alloc under memory pressure above all) is caught there, every worker is joined, and the
// first exception is thrown again on the calling thread, where the same error path as a one-thread
// run reports it.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace tactile {

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

// Runs work() on `threads` threads, the calling thread being one of them (threads <= 1: only the
// calling thread), and returns when all have returned. An exception thrown by work() on any thread,
// or by starting a thread, is caught; after every started thread has been joined the first one is
// thrown again here. `failed`, when given, collects the exceptions instead of a local keeper, so
// that work() can ask failed->failed() and stop taking new tasks once any worker has thrown.
inline void runWorkers(unsigned threads, const std::function<void()>& work,
                       FirstException* failed = nullptr) {
  FirstException local;
  FirstException& first = failed != nullptr ? *failed : local;
  std::vector<std::thread> pool;
  if (threads > 1) {
    first.capture([&] {
      pool.reserve(threads - 1);
      for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back([&] { first.capture(work); });
    });
  }
  first.capture(work);
  for (std::thread& t : pool)
    t.join();
  first.rethrow();
}

}  // namespace tactile
