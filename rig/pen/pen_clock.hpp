// The clock libinput stamps tablet events with (the kernel's CLOCK_MONOTONIC), read now: what a
// periodic tick compares a pen's last report with.
#pragma once

#include <ctime>

namespace nibrig::rig::pen {

inline double pen_clock_now_s() noexcept {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace nibrig::rig::pen
