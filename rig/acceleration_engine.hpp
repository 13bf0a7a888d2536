// The real-time engine as a source of acceleration in m/s² rather than of output level: the rig
// simulates tools with it (the simulated rig's tool, the live comparison's simulation) and wants
// the tip's acceleration back, not what an actuator should receive.
#pragma once

#include <cstdint>
#include <memory>

#include "model/design/tool_sound.hpp"
#include "playback/prepared_engine.hpp"
#include "rt/stroke_source.hpp"

namespace nibrig::rig {

// The engine's output level is set to 1 / this, so output × this is m/s². The output stage's
// limiter (0.9 of full scale) then sits at 450 m/s², far above any drawing tool (a few m/s²), and
// only its 5 Hz DC blocker acts — as an accelerometer's own AC coupling would.
inline constexpr double kEngineHeadroom_m_s2 = 500.0;

// A one-voice engine playing `sound` at `rate_hz`, moved by `stroke`, with output in units of
// kEngineHeadroom_m_s2.
inline std::unique_ptr<playback::PreparedEngine> acceleration_engine(
    const model::design::ToolSound& sound, double rate_hz, std::unique_ptr<rt::StrokeSource> stroke,
    std::uint64_t seed) {
  rt::EngineSettings settings;
  settings.sample_rate_hz = rate_hz;
  settings.slots = 1;
  settings.output_level_per_m_s2 = 1.0 / kEngineHeadroom_m_s2;
  return std::make_unique<playback::PreparedEngine>(settings, sound, std::move(stroke), seed);
}

}  // namespace nibrig::rig
