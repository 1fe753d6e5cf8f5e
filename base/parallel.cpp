#include "base/parallel.h"

#include <algorithm>
#include <condition_variable>
#include <cstdint>

namespace tactile {

unsigned workerThreadCount(unsigned requested, std::size_t items) {
  const unsigned asked = requested != 0 ? requested : std::thread::hardware_concurrency();
  return static_cast<unsigned>(std::clamp<std::size_t>(
      std::min<std::size_t>({asked, kMaxWorkerThreads, items}), 1, kMaxWorkerThreads));
}

BackgroundWorkers::BackgroundWorkers(unsigned threads, std::function<void()> work,
                                     FirstException& failure)
    : work_(std::move(work)) {
  failure.capture([&] {
    threads_.reserve(threads);
    for (unsigned t = 0; t < threads; ++t)
      threads_.emplace_back([this, &failure] { failure.capture(work_); });
  });
}

void BackgroundWorkers::join() {
  for (std::thread& t : threads_)
    if (t.joinable()) t.join();
}

namespace detail {

bool parallelForIndices(std::size_t count, unsigned threads,
                        const std::function<bool(std::size_t)>& body) {
  if (count == 0) return true;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stopped{false};
  FirstException failure;
  const auto work = [&] {
    while (!stopped.load(std::memory_order_relaxed) && !failure.failed()) {
      const std::size_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= count) return;
      if (!body(i)) stopped.store(true, std::memory_order_relaxed);
    }
  };
  {
    const unsigned n = workerThreadCount(threads, count);
    // The helpers are joined when the block ends; the caller's own share never throws out of it.
    BackgroundWorkers helpers(n - 1, work, failure);
    failure.capture(work);
  }
  failure.rethrow();
  return !stopped.load() && next.load() >= count;
}

}  // namespace detail

namespace {

thread_local bool tInsidePart = false;

inline void cpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// Spin this many rounds (tens of microseconds) waiting for work or for helpers before sleeping:
// EM and k-means hand out a job every fraction of a millisecond, and waking a sleeping thread
// costs about as much as a part.
constexpr int kSpinRounds = 20000;

class Pool {
 public:
  explicit Pool(int workers) {
    threads_.reserve(static_cast<std::size_t>(workers));
    for (int w = 0; w < workers; ++w)
      threads_.emplace_back([this, w] { loop(w); });
  }
  int workers() const { return static_cast<int>(threads_.size()); }

  // Caller holds `busy`. Runs the job with `helpers` workers besides the calling thread.
  void run(int parts, int helpers, const std::function<void(int)>& f) {
    job_ = &f;
    parts_ = parts;
    helpers_ = helpers;
    next_.store(0, std::memory_order_relaxed);
    // Every worker acknowledges every job (those beyond `helpers` without working), so none can
    // still be reading this job's fields when the next one is written.
    pending_.store(workers(), std::memory_order_relaxed);
    {
      // Under the mutex, so that a worker about to sleep cannot miss the new generation.
      std::lock_guard<std::mutex> lock(mutex_);
      generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    work();
    for (int i = 0; i < kSpinRounds && pending_.load(std::memory_order_acquire) != 0; ++i)
      cpuRelax();
    if (pending_.load(std::memory_order_acquire) != 0) {
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, [this] { return pending_.load(std::memory_order_acquire) == 0; });
    }
    job_ = nullptr;
    // A part that threw (on any thread): every thread has left the job, so throw it here.
    std::exception_ptr failure;
    {
      std::lock_guard<std::mutex> lock(failureMutex_);
      failure = std::exchange(failure_, nullptr);
    }
    if (failure) std::rethrow_exception(failure);
  }

  std::mutex busy;

 private:
  // Runs parts until none is left. An exception from a part is kept for run() to throw on the
  // calling thread (never let out of a pool thread, which would end the process), and no further
  // part is handed out.
  void work() {
    const bool wasInside = tInsidePart;
    tInsidePart = true;
    try {
      for (int p = next_.fetch_add(1, std::memory_order_relaxed); p < parts_;
           p = next_.fetch_add(1, std::memory_order_relaxed))
        (*job_)(p);
    } catch (...) {
      std::lock_guard<std::mutex> lock(failureMutex_);
      if (!failure_) failure_ = std::current_exception();
      next_.store(parts_, std::memory_order_relaxed);
    }
    tInsidePart = wasInside;
  }

  void loop(int index) {
    std::uint64_t seen = 0;
    for (;;) {
      std::uint64_t g = generation_.load(std::memory_order_acquire);
      for (int i = 0; i < kSpinRounds && g == seen; ++i) {
        cpuRelax();
        g = generation_.load(std::memory_order_acquire);
      }
      if (g == seen) {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] {
          g = generation_.load(std::memory_order_acquire);
          return g != seen;
        });
      }
      seen = g;
      if (index < helpers_) work();
      if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        std::lock_guard<std::mutex> lock(mutex_);
        done_.notify_one();
      }
    }
  }

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  // Written by the caller before the generation is published (release), read by the workers
  // after they see it (acquire).
  const std::function<void(int)>* job_ = nullptr;
  int parts_ = 0;
  int helpers_ = 0;
  std::atomic<int> next_{0};
  std::atomic<int> pending_{0};
  std::atomic<std::uint64_t> generation_{0};
  std::mutex failureMutex_;
  std::exception_ptr failure_;  // the first exception of the current job's parts
};

// Created on first use and never destroyed (its threads wait for work until the process ends).
Pool& pool() {
  static Pool* p = new Pool(std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1));
  return *p;
}

}  // namespace

void pooledParallelFor(int parts, int threads, const std::function<void(int)>& f) {
  if (parts <= 0) return;
  threads = std::min(threads, parts);
  if (threads > 1 && !tInsidePart) {
    Pool& p = pool();
    std::unique_lock<std::mutex> lock(p.busy, std::try_to_lock);
    if (lock.owns_lock()) {
      p.run(parts, std::min(threads - 1, p.workers()), f);
      return;
    }
  }
  for (int part = 0; part < parts; ++part)
    f(part);
}

}  // namespace tactile
