// Flush-to-zero for the audio thread: decaying modes and filter tails reach subnormal numbers
// after a silence, and arithmetic on those is up to a hundred times slower on x86, enough to
// overrun a callback. The guard sets FTZ and DAZ for its scope and restores the caller's mode
// (the offline render runs on an ordinary thread).
#pragma once

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace nibrig::rt {

class DenormalGuard {
 public:
#if defined(__SSE2__)
  DenormalGuard() noexcept : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero); }
  ~DenormalGuard() { _mm_setcsr(saved_); }

 private:
  static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
  unsigned saved_;
#else
  // Other architectures: no portable switch; the output stage still flushes its own state.
  DenormalGuard() noexcept = default;
#endif
  DenormalGuard(const DenormalGuard&) = delete;
  DenormalGuard& operator=(const DenormalGuard&) = delete;
};

}  // namespace nibrig::rt
