#include "ui/cli/interrupt_scope.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

namespace nibrig::ui::cli {

namespace {

constexpr char kInterrupt = 'i', kQuit = 'q';
volatile std::sig_atomic_t wake_fd = -1;

extern "C" void on_interrupt_signal(int) {
  const int fd = wake_fd;
  if (fd < 0) return;
  const char c = kInterrupt;
  [[maybe_unused]] const auto n = ::write(fd, &c, 1);
}

}  // namespace

InterruptScope::InterruptScope() {
  if (::pipe2(pipe_, O_CLOEXEC) != 0)
    throw std::system_error(errno, std::generic_category(), "Ctrl-C's wake-up pipe");
  watcher_ = std::thread([this] {
    for (;;) {
      char c = 0;
      const auto n = ::read(pipe_[0], &c, 1);
      if (n < 0 && errno == EINTR) continue;
      if (n != 1 || c == kQuit) return;
      source_.request_stop();
    }
  });
  wake_fd = pipe_[1];
  previous_ = std::signal(SIGINT, on_interrupt_signal);
}

InterruptScope::~InterruptScope() {
  std::signal(SIGINT, previous_);
  wake_fd = -1;
  const char c = kQuit;
  while (::write(pipe_[1], &c, 1) < 0 && errno == EINTR) {
  }
  watcher_.join();
  ::close(pipe_[0]);
  ::close(pipe_[1]);
}

}  // namespace nibrig::ui::cli
