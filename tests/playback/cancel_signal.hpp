// glibc's thread-cancellation signal (SIGCANCEL) held back or let in for the calling thread, below
// glibc, whose sigprocmask refuses to block it: a test then chooses where an asynchronous cancel
// lands, as a loaded machine now and then does by delaying the signal.
#pragma once

#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace nibrig::playback::testing {

// A global, not a local: ASan leaves the locals of a frame that a cancellation unwound poisoned on
// the thread's stack, and its own thread exit then trips over them.
inline constexpr unsigned long kCancelSignalSet = 1ul << (__SIGRTMIN - 1);

inline void hold_cancel_signal(bool hold) {
  syscall(SYS_rt_sigprocmask, hold ? SIG_BLOCK : SIG_UNBLOCK, &kCancelSignalSet, nullptr,
          sizeof kCancelSignalSet);
}

}  // namespace nibrig::playback::testing
