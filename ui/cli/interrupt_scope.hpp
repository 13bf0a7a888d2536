// Ctrl-C during a run on a rig or a design loop: the motor stops and the session is finished with
// what it holds. While an InterruptScope lives, SIGINT requests a stop of its token instead of
// ending the process; the library's jobs take that token as they take any other.
#pragma once

#include <csignal>
#include <stop_token>
#include <thread>

namespace nibrig::ui::cli {

class InterruptScope {
 public:
  // Throws std::system_error when the signal's wake-up pipe cannot be made. One at a time.
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  std::stop_token token() const { return source_.get_token(); }
  bool interrupted() const { return source_.stop_requested(); }

 private:
  void (*previous_)(int);
  std::stop_source source_;
  int pipe_[2] = {-1, -1};
  // A signal handler may only write to a pipe; this thread reads it and requests the stop.
  std::thread watcher_;
};

}  // namespace nibrig::ui::cli
