// What the fault tests on the simulated board ask of the firmware: when the frames first carried a
// fault's flag, when the disc truly came to rest, and that the drive stayed off from then on.
#pragma once

#include <cstdint>
#include <optional>

#include "tests/rig/usb/board_host.hpp"

namespace nibrig::rig::usb::testing {

// The sample instant (simulated us) of the first frame after `after_us` carrying `flag`.
std::optional<double> first_flagged(const BoardHost& host, std::uint16_t flag, double after_us);

// The first millisecond record after `after_us` from which the disc's true surface speed stays under
// 0.1 mm/s (a count in 0.8 s: at rest) to the end of the record.
std::optional<double> disc_at_rest_since(const BoardHost& host, double after_us);

// Every frame sampled from a loop tick after `from_us` carries `flag` and no longer
// kProfileRunning, and the bridge's duty has been 0 since.
void expect_stopped_since(const BoardHost& host, std::uint16_t flag, double from_us);

// Turns the disc at `speed` mm/s for 0.3 s with the stream on, does `fault` to it, then runs 0.7 s:
// returns the instant it was done.
template <typename F>
double run_into_fault(BoardHost& host, double speed, F fault) {
  host.require_out(Request::kSetStreaming, 1);
  host.set_speed_mm_s(static_cast<float>(speed));
  host.run_us(300'000.0);
  host.clear_records();
  const double at = host.sim_us();
  fault();
  host.run_us(700'000.0);
  return at;
}

}  // namespace nibrig::rig::usb::testing
