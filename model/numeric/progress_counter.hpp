// Progress of long model work counted in units (a fit start, a bootstrap refit, a fold): the
// callback type faces pass in, and a counter that jobs running in parallel_for share to report
// each finished unit exactly once.
#pragma once

#include <cstddef>
#include <functional>
#include <mutex>
#include <utility>

namespace nibrig::model::numeric {

// Called once per finished unit with done = 1..total. Empty: nobody is watching.
using Progress = std::function<void(std::size_t done, std::size_t total)>;

class ProgressCounter {
 public:
  ProgressCounter(Progress progress, std::size_t total)
      : progress_(std::move(progress)), total_(total) {}

  // Thread-safe. The call is made under the lock, so a callback need not be thread-safe itself
  // and sees done counts in increasing order even when units finish on several threads.
  void finished() {
    if (!progress_) return;
    std::lock_guard lock(mutex_);
    progress_(++done_, total_);
  }

 private:
  Progress progress_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::mutex mutex_;
};

}  // namespace nibrig::model::numeric
