// Ctrl-C during a run on a rig: the motor stops and the session is finished with what it holds.
// While an InterruptScope lives, SIGINT sets `interrupt_requested()` instead of ending the process.
#pragma once

#include <atomic>
#include <csignal>

namespace nibrig::ui::cli {

const std::atomic<bool>& interrupt_requested();

class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  void (*previous_)(int);
};

}  // namespace nibrig::ui::cli
