// One sample of the turntable's slow sensors, as every rig (USB controller, simulated, replayed)
// delivers it: the device's own clock and sequence number, the encoder's speed and the two force
// channels, with flags for what was wrong at that instant. The USB wire format that carries it is
// rig/PROTOCOL.md; this is the decoded, unit-bearing form.
#pragma once

#include <cstdint>

namespace nibrig::rig {

// Bits of SensorFrame::flags. The values are the wire format's (PROTOCOL.md) so a frame's flags are
// copied, never translated.
enum SensorFlag : std::uint16_t {
  kNormalForceSaturated = 1u << 0,      // the normal channel is at its converter's end
  kTangentialForceSaturated = 1u << 1,  // the tangential channel is at its converter's end
  kEncoderFault = 1u << 2,              // the speed reading is not trustworthy (lost index, glitch)
  kMotorFault = 1u << 3,                // stall, over-current, driver, supply, over-speed or slip
  kWatchdogStopped = 1u << 4,           // the motor stopped because the host was silent too long
  kProfileRunning = 1u << 5,            // a profile (or a speed target) is being followed
  kForceFault = 1u << 6,                // a force channel stopped the motor (1.2): unusable while it turned
};

struct SensorFrame {
  std::uint64_t device_time_us = 0;  // the device's free-running microsecond clock
  std::uint32_t sequence = 0;        // +1 per frame; a gap is frames lost on the way
  float speed_m_s = 0.0f;            // the turntable's surface speed under the tip (encoder)
  float normal_force_N = 0.0f;       // calibrated on the device: counts / (counts per N) × lever
  float tangential_force_N = 0.0f;
  std::uint16_t flags = 0;  // SensorFlag bits
  // When the host received it, on its steady clock (ns): the USB driver stamps each packet as its
  // transfer completes, for the time base (rig/clock_fit.hpp). 0 where no host received it (the
  // simulated and replay rigs, whose frames are on the capture's timeline already).
  std::int64_t host_ns = 0;
};

}  // namespace nibrig::rig
