#include "ui/cli/interrupt_scope.hpp"

namespace nibrig::ui::cli {

namespace {
std::atomic<bool> interrupt_flag{false};
extern "C" void on_interrupt_signal(int) { interrupt_flag.store(true); }
}  // namespace

const std::atomic<bool>& interrupt_requested() { return interrupt_flag; }

InterruptScope::InterruptScope() : previous_(std::signal(SIGINT, on_interrupt_signal)) {
  interrupt_flag.store(false);
}

InterruptScope::~InterruptScope() { std::signal(SIGINT, previous_); }

}  // namespace nibrig::ui::cli
