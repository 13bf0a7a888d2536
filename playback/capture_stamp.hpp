// When captured audio arrived, as the audio thread notes it for a time base (see CaptureStamp).
#pragma once

#include <cstdint>

namespace nibrig::playback {

// When a callback's captured input arrived: the index of its first sample in the capture's timeline
// (every sample the device delivered, stored or dropped) and the host's steady clock (ns) at the
// callback's start. A time base (rig/clock_fit.hpp) puts the captured samples on the host clock
// from these.
struct CaptureStamp {
  std::uint64_t first_sample = 0;
  std::int64_t host_ns = 0;
};

}  // namespace nibrig::playback
