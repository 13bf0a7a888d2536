// The CPU time of the audio thread's blocks, for counting overruns: work that did not fit its
// period, as opposed to time the thread was preempted (a shared machine without real-time
// scheduling preempts it; that shows in the device's xruns and the wall-time histogram instead).
// The thread's CPU clock is a system call (no vDSO) that costs as much as rendering a light block,
// so it is not read at every block: only at a block's start once an eighth of a period of wall time
// has passed since the last reading, and at the end of a block that took longer than its period.
// A block's CPU time is then bounded above by its wall time and by the CPU time since the last
// reading, which exceeds the block's own by at most that eighth of a period. In real time a block
// starts a period after the last, so each is read; rendering faster than real time (offline, a
// study's stimuli made at once) reads the clock only every so often. A reading is the calling
// thread's, so a block on another thread than the last reading's is read anew.
#pragma once

#include <pthread.h>

#include <cstdint>

namespace nibrig::rt {

class BlockCpuClock {
 public:
  // Times in seconds on a monotonic wall clock. Real-time safe.
  void block_starts(double wall_now_s, double period_s) noexcept;
  // An upper bound on the block's CPU time, at most its wall time; exact to within period/8 for a
  // block past its period.
  double block_ends(double wall_seconds, double period_s) noexcept;
  std::uint64_t readings() const noexcept { return readings_; }

 private:
  double read() noexcept;

  double cpu_mark_s_ = 0, wall_mark_s_ = 0;
  bool marked_ = false;
  pthread_t thread_{};
  std::uint64_t readings_ = 0;
};

}  // namespace nibrig::rt
