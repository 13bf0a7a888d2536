// The rig without hardware: a turntable whose motor follows the profile through a first-order speed
// loop, an arm pressing with its load, a tool whose vibration is the engine's simulation of it on
// the surface, driven by the speed the motor actually reaches. Everything a real rig adds is here
// too, at stated levels: the motor's own vibration line (the paper's Fig. 6: a weak line whose
// frequency rises with speed), encoder, force and accelerometer noise, converters that saturate.
// Deterministic for a seed: two captures with one seed are equal to the bit.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

#include "model/design/tool_sound.hpp"
#include "rig/accelerometer_input.hpp"
#include "rig/pacer.hpp"
#include "rig/rig.hpp"
#include "rt/reference_load.hpp"

namespace nibrig::rig {

struct SimulatedRigSettings {
  double frame_rate_hz = 1000.0;
  double acceleration_rate_hz = 48000.0;
  double normal_load_N = rt::kReferenceNormalForce;  // the paper's mean drawing force
  double mu = 0.3;              // tangential / normal force while sliding
  double max_speed_m_s = 0.4;   // the motor follows 0..this
  double motor_time_constant_s = 0.05;  // the speed loop settles to 1 % in 0.23 s
  // The motor's vibration: a sinusoid at speed × this (Hz per m/s) of this amplitude. Weak, as on
  // the paper's oiled acrylic, where only the motor line and a faint background remain.
  double motor_line_hz_per_m_s = 2000.0;
  double motor_line_m_s2 = 0.002;
  double encoder_noise_m_s = 0.0003;   // rms
  double force_noise_N = 0.005;        // rms, each channel
  double accelerometer_noise_m_s2 = 0.002;  // rms, white over the audio band
  double normal_full_scale_N = 10.0;   // readings beyond are clipped and flagged
  double tangential_full_scale_N = 5.0;
  // The acceleration is stored as an audio interface would hold it: full scale = this many m/s²
  // (a ±5 g accelerometer on a line input).
  double accelerometer_m_s2_per_unit = kDefaultAccelerometerM_s2;
  // 1 = real time (read() waits for the clock), k > 1 = k times faster, 0 = as fast as it computes.
  double speedup = 1.0;
  std::uint64_t seed = 1;
};

class SimulatedRig final : public Rig {
 public:
  // `sound` is the tool on the surface (model::design::ToolSounds); it is copied. Throws
  // std::invalid_argument for settings out of range (naming the setting).
  SimulatedRig(const SimulatedRigSettings& settings, const model::design::ToolSound& sound,
               const std::string& tool, const std::string& surface);
  ~SimulatedRig() override;

  // The seed of the simulated tool's forcing noise for a rig seeded `seed`: not `seed` itself, so
  // that a comparison's simulation seeded alike (rig compare --seed) does not replay the very noise
  // the rig's tool made — a real tool never would.
  static std::uint64_t tool_seed(std::uint64_t seed) { return seed ^ 0x7001'5eedULL; }

  const RigDescription& description() const override { return description_; }
  void start(const SpeedProfile& profile) override;
  bool read(RigData& into, std::chrono::milliseconds wait) override;
  void stop() override;
  RigHealth health() const override { return health_; }

 private:
  struct Simulation;
  void produce_block(RigData& into);

  SimulatedRigSettings settings_;
  RigDescription description_;
  model::design::ToolSound sound_;
  std::unique_ptr<Simulation> simulation_;
  std::optional<SpeedProfile> profile_;
  RigHealth health_;
  std::uint64_t frames_made_ = 0, frames_total_ = 0, samples_made_ = 0;
  Pacer pacer_;
  bool stopped_ = false;
};

}  // namespace nibrig::rig
