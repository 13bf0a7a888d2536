// Long work off the UI thread (a fit, a bootstrap, a search, the FEM grid): the job runs on a
// thread of its own and reports progress and a message; the UI reads them each frame, never waits,
// and may ask it to stop. The result or the error comes back once, when the UI next looks.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>

namespace nibrig::ui::panel {

// What a job sees: whether it was asked to stop, and where to report.
class JobControl {
 public:
  bool stop_requested() const { return stop_.stop_requested(); }
  std::stop_token stop_token() const { return stop_; }
  void progress(double fraction) { fraction_->store(fraction, std::memory_order_relaxed); }
  void message(std::string text);

 private:
  template <typename> friend class BackgroundJob;
  JobControl(std::stop_token stop, std::atomic<double>* fraction, std::mutex* mutex, std::string* message)
      : stop_(std::move(stop)), fraction_(fraction), mutex_(mutex), message_(message) {}
  std::stop_token stop_;
  std::atomic<double>* fraction_;
  std::mutex* mutex_;
  std::string* message_;
};

inline void JobControl::message(std::string text) {
  std::lock_guard lock(*mutex_);
  *message_ = std::move(text);
}

// A model's progress by step (its name, done of total) on a job's bar, the message `prefix` + the
// step's name: the form the cached defaults and the space fit report in.
inline auto step_reporter(JobControl& control, std::string prefix) {
  return [&control, prefix = std::move(prefix)](const std::string& step, std::size_t done, std::size_t total) {
    control.message(prefix + step);
    control.progress(total ? static_cast<double>(done) / static_cast<double>(total) : 0.0);
  };
}

// Called on a job's own thread as any job ends: the window sets it to wake its idle wait, so that
// what a job made is shown at once (panel_window.hpp).
inline std::atomic<void (*)()> job_done_hook{nullptr};

template <typename Result>
class BackgroundJob {
 public:
  // Starts `work` now. An exception it throws becomes error().
  explicit BackgroundJob(std::string title, std::function<Result(JobControl&)> work)
      : title_(std::move(title)) {
    thread_ = std::jthread([this, work = std::move(work)](std::stop_token stop) {
      JobControl control(stop, &fraction_, &mutex_, &message_);
      try {
        Result result = work(control);
        std::lock_guard lock(mutex_);
        result_ = std::move(result);
      } catch (const std::exception& e) {
        std::lock_guard lock(mutex_);
        error_ = e.what();
      }
      done_.store(true, std::memory_order_release);
      if (auto hook = job_done_hook.load()) hook();
    });
  }
  // Asks the job to stop and joins it (work checks stop_requested() often).
  ~BackgroundJob() { thread_.request_stop(); }

  const std::string& title() const { return title_; }
  bool done() const { return done_.load(std::memory_order_acquire); }
  double progress() const { return fraction_.load(std::memory_order_relaxed); }
  std::string message() const {
    std::lock_guard lock(mutex_);
    return message_;
  }
  void cancel() { thread_.request_stop(); }
  bool cancelled() const { return thread_.get_stop_token().stop_requested(); }
  // Once done: the result (moved out: the first call only) or the error message.
  std::optional<Result> take_result() {
    if (!done()) return std::nullopt;
    std::lock_guard lock(mutex_);
    auto r = std::move(result_);
    result_.reset();
    return r;
  }
  std::string error() const {
    if (!done()) return {};
    std::lock_guard lock(mutex_);
    return error_;
  }

 private:
  std::string title_;
  std::atomic<double> fraction_{0.0};
  std::atomic<bool> done_{false};
  mutable std::mutex mutex_;
  std::string message_, error_;
  std::optional<Result> result_;
  std::jthread thread_;  // last: joined first on destruction, while the rest still exists
};

}  // namespace nibrig::ui::panel
