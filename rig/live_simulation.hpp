// The simulation of a tool driven by what the rig measures: each sensor frame's speed and normal
// force go to the engine's live contact (rt::Engine::set_contact) and the engine renders the
// acceleration samples of that frame's span, so the simulated stream runs sample for sample beside
// the measured one and follows the turntable within one frame (1 ms at 1 kHz). Runs on the thread
// that reads the rig, never an audio thread; the actuator's engine (--play) is another engine.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "model/design/tool_sound.hpp"
#include "playback/prepared_engine.hpp"
#include "rig/rig.hpp"

namespace nibrig::rig {

class LiveSimulation {
 public:
  // Throws std::invalid_argument for rates that are not positive, or what the engine refuses.
  LiveSimulation(const model::design::ToolSound& sound, double acceleration_rate_hz,
                 double frame_rate_hz, std::uint64_t seed);
  ~LiveSimulation();

  // Appends to `simulated_m_s2` one simulated sample (m/s²) per measured acceleration sample in
  // `data`. Frame k covers samples [k·r, (k+1)·r), r = acceleration rate / frame rate; samples
  // whose frame has not arrived yet keep the newest contact, frames ahead of the samples wait.
  void feed(const RigData& data, std::vector<float>& simulated_m_s2);

  std::uint64_t samples() const { return samples_; }

 private:
  std::unique_ptr<playback::PreparedEngine> session_;
  double samples_per_frame_;
  std::vector<SensorFrame> pending_;  // frames not yet rendered, the first being frame first_
  std::uint64_t first_ = 0;           // index of pending_[0] among all frames received
  std::uint64_t samples_ = 0;         // simulated samples made
  std::vector<float> block_;
};

}  // namespace nibrig::rig
