#include "analysis/parallel.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace tactile {
namespace {

thread_local bool tInsidePart = false;

class Pool {
 public:
  explicit Pool(int workers) {
    threads_.reserve(static_cast<std::size_t>(workers));
    for (int w = 0; w < workers; ++w)
      threads_.emplace_back([this, w] { loop(w); });
  }
  int workers() const { return static_cast<int>(threads_.size()); }

  // Caller holds busy_. Runs the job with `helpers` workers besides the calling thread.
  void run(int parts, int helpers, const std::function<void(int)>& f) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &f;
      parts_ = parts;
      next_.store(0, std::memory_order_relaxed);
      helpers_ = helpers;
      pending_ = helpers;
      ++generation_;
    }
    wake_.notify_all();
    work();
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    job_ = nullptr;
  }

  std::mutex busy;

 private:
  void work() {
    const bool wasInside = tInsidePart;
    tInsidePart = true;
    for (int p = next_.fetch_add(1, std::memory_order_relaxed); p < parts_;
         p = next_.fetch_add(1, std::memory_order_relaxed))
      (*job_)(p);
    tInsidePart = wasInside;
  }

  void loop(int index) {
    std::uint64_t seen = 0;
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return generation_ != seen; });
        seen = generation_;
        if (index >= helpers_) continue;
      }
      work();
      {
        std::lock_guard<std::mutex> lock(mutex_);
        --pending_;
      }
      done_.notify_one();
    }
  }

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int)>* job_ = nullptr;
  int parts_ = 0;
  std::atomic<int> next_{0};
  int helpers_ = 0;
  int pending_ = 0;
  std::uint64_t generation_ = 0;
};

// Created on first use and never destroyed (its threads wait for work until the process ends).
Pool& pool() {
  static Pool* p = new Pool(std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1));
  return *p;
}

}  // namespace

void parallelFor(int parts, int threads, const std::function<void(int)>& f) {
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
