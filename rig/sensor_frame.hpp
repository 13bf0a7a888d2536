// One sample of the turntable's slow sensors, as every rig (USB controller, simulated, replayed)
// delivers it: the device's own clock and sequence number, the encoder's speed and the two force
// channels, with flags for what was wrong at that instant. The USB wire format that carries it is
// rig/PROTOCOL.md; this is the decoded, unit-bearing form.
#pragma once

#include <cstdint>

#include "rig/firmware/rig_protocol.h"

namespace nibrig::rig {

// Bits of SensorFrame::flags. The values are the wire format's (rig/firmware/rig_protocol.h) so a
// frame's flags are copied, never translated.
enum SensorFlag : std::uint16_t {
  kNormalForceSaturated = RIG_NORMAL_SATURATED,  // the normal channel is at its converter's end
  kTangentialForceSaturated = RIG_TANGENTIAL_SATURATED,  // the tangential channel, likewise
  kEncoderFault = RIG_ENCODER_FAULT,  // the speed reading is not trustworthy (lost index, glitch)
  kMotorFault = RIG_MOTOR_FAULT,      // stall, over-current, driver, supply, over-speed or slip
  kWatchdogStopped = RIG_WATCHDOG_STOPPED,  // the motor stopped: the host was silent too long
  kProfileRunning = RIG_PROFILE_RUNNING,    // a profile (or a speed target) is being followed
  kForceFault =
      RIG_FORCE_FAULT,  // a force channel stopped the motor (1.2): unusable while it turned
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
