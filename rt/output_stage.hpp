// The last stage before the actuator (ARCHITECTURE.md, "Real-time rules"): a DC blocker, a guard that turns
// NaN and infinity into silence, and a peak limiter, so that a voice-coil actuator never receives a
// full-scale step, a DC offset or a non-finite sample whatever a voice computes. Runs on the audio
// thread: process() never allocates, locks or throws.
#pragma once

#include <cstddef>
#include <cstdint>

namespace nibrig::rt {

struct OutputStageSettings {
  double sample_rate_hz = 48000.0;
  // DC blocker: a one-pole high-pass at this corner. 5 Hz is below the 20-500 Hz band the actuator
  // renders and far below human vibrotactile sensitivity's useful range.
  double dc_corner_hz = 5.0;
  double limit = 0.9;      // the largest output magnitude, in output units (full scale = 1)
  double release_s = 0.05;  // the limiter's gain recovers with this time constant
};

struct OutputStageCounts {
  std::uint64_t non_finite_samples = 0;  // NaN or ±inf replaced by silence
  std::uint64_t limited_samples = 0;     // samples the limiter attenuated
  double peak = 0.0;                     // largest |output| so far
};

class OutputStage {
 public:
  // Throws std::invalid_argument for a non-positive rate, corner, limit or release, or a corner at
  // or above Nyquist (on a control thread, at construction).
  explicit OutputStage(const OutputStageSettings& settings);

  // In place. |output| ≤ limit for every sample, whatever the input.
  void process(float* samples, std::size_t count) noexcept;

  const OutputStageCounts& counts() const noexcept { return counts_; }
  double dc_pole() const noexcept { return pole_; }
  // The limiter's gain now: 1 when it is not attenuating.
  double gain() const noexcept { return gain_; }

 private:
  static constexpr std::size_t kChunk = 64;  // samples filtered together, in a stack array

  void high_pass_grouped(const float* in, double* out, std::size_t count) noexcept;
  void high_pass_guarded(const float* in, double* out, std::size_t count) noexcept;
  void limit(const double* in, float* out, std::size_t count) noexcept;

  double pole_;          // R of y[n] = x[n] − x[n−1] + R·y[n−1]
  double pole_powers_[4];  // R, R², R³, R⁴
  double release_step_;  // per-sample approach of the gain back towards 1
  double limit_;
  float limit_float_;
  double previous_input_ = 0.0, previous_output_ = 0.0;
  double gain_ = 1.0;
  OutputStageCounts counts_;
};

}  // namespace nibrig::rt
