// Progress of long model work counted in units (a fit start, a bootstrap refit, a fold): the
// callback type faces pass in, and a counter that jobs running in parallel_for share to report
// each finished unit exactly once.
#pragma once

#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <utility>

namespace nibrig::model::numeric {

// Called once per finished unit with done = 1..total. Empty: nobody is watching.
using Progress = std::function<void(std::size_t done, std::size_t total)>;

// Progress of work made of several steps, each counted in its own units ("fit starts", then
// "bootstrap refits"): each step is announced with done = 0 as it begins (so a window can name what
// it is waiting for before the first unit finishes), then called once per finished unit.
using StepProgress =
    std::function<void(const std::string& step, std::size_t done, std::size_t total)>;

// The Progress of one step: announces it (done = 0 of `total`) now and forwards every unit.
// Empty when `progress` is.
inline Progress step_progress(const StepProgress& progress, const std::string& step,
                              std::size_t total) {
  if (!progress) return {};
  progress(step, 0, total);
  return [progress, step](std::size_t done, std::size_t all) { progress(step, done, all); };
}

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
