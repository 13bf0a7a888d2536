#include "rt/block_cpu_clock.hpp"

#include <time.h>

#include <algorithm>

namespace nibrig::rt {

double BlockCpuClock::read() noexcept {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  ++readings_;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void BlockCpuClock::block_starts(double wall_now_s, double period_s) noexcept {
  const pthread_t self = pthread_self();
  if (marked_ && pthread_equal(self, thread_) && wall_now_s - wall_mark_s_ <= period_s / 8) return;
  thread_ = self;
  cpu_mark_s_ = read();
  wall_mark_s_ = wall_now_s;
  marked_ = true;
}

double BlockCpuClock::block_ends(double wall_seconds, double period_s) noexcept {
  // A thread's CPU time within an interval never exceeds the interval.
  if (wall_seconds <= period_s) return wall_seconds;
  const double now = read();
  const double cpu = std::min(wall_seconds, now - cpu_mark_s_);
  cpu_mark_s_ = now;
  wall_mark_s_ += wall_seconds;  // at most the block's end: the next block then reads if it must
  return cpu;
}

}  // namespace nibrig::rt
