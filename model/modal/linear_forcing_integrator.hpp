// The streaming integrator of a whole ModalModel under a sampled force, joined linearly between
// samples (exact for that force): a two-pole recursion per mode, state in preallocated
// structure-of-arrays, and a process() that neither allocates, locks nor throws, for rt/ to run on
// the audio thread. Everything that can fail happens in the constructor.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "model/modal/modal_model.hpp"

namespace nibrig::model::modal {

class LinearForcingIntegrator {
 public:
  // Precomputes Φ, Γ₀, Γ₁ of every mode for the step 1/sample_rate. Throws std::invalid_argument on
  // a bad model or sample rate. Starts at rest (see reset()).
  LinearForcingIntegrator(const ModalModel& model, double sample_rate);

  std::size_t modes() const noexcept { return modes_; }
  double sample_rate() const noexcept { return sample_rate_; }

  // Every mode at rest and no force seen yet: the next sample processed is the time origin, where
  // the force may jump from 0 to its first value (as simulate_sinusoids starts at t = 0).
  void reset() noexcept;

  // How the time origin starts (after construction or reset()): at rest, the force jumping from 0
  // (the default, the closed forms' convention), or with the quasi-static modes in equilibrium
  // under the first force: every overdamped mode (ζ ≥ 1) and every mode above the step's Nyquist
  // frequency held still at b·f/ω², as in a stylus already in steady contact; the resonant ones
  // at rest, since a still resonant mode is no likelier a state than rest. A voice that joins a
  // stroke in progress starts so: from rest, the jump reached the sensor whole through the stiff
  // modes' Σ c·b, and a printed design's first millisecond clicked at 8× its level.
  enum class Start { at_rest, in_equilibrium };
  void set_start(Start start) noexcept { start_ = start; }

  // Sets the state at the time of the last processed sample, whose force was `force` (N). Throws
  // std::invalid_argument on sizes other than modes() or non-finite values. Not for the audio
  // thread.
  void set_state(std::span<const double> displacement, std::span<const double> velocity,
                 double force);
  // The state of mode < modes() at the last processed sample (unchecked: read on the audio thread).
  double displacement(std::size_t mode) const noexcept { return q_[mode]; }
  double velocity(std::size_t mode) const noexcept { return v_[mode]; }

  // For each n: takes f(t_n) = force[n] (N), advances the modes from t_{n−1} (force linear in
  // between) and writes the sensor acceleration a(t_n) (m/s²). force and acceleration may be the
  // same buffer. Real-time safe: no allocation, lock or exception; cost ≈ 12 multiply-adds per mode
  // per sample. The state is double whatever the buffers. Decaying modes reach subnormal numbers
  // after a long silence: the caller (rt/) runs with flush-to-zero set.
  void process(const float* force, float* acceleration, std::size_t count) noexcept;
  void process(const double* force, double* acceleration, std::size_t count) noexcept;

 private:
  template <class Sample>
  void run(const Sample* force, Sample* acceleration, std::size_t count) noexcept;

  std::size_t modes_;
  std::size_t padded_;  // modes_ rounded up to the lane count; padding modes are zero throughout
  double sample_rate_;
  // Per mode, padded: Φ, Γ₀ and Γ₁ scaled by b, and the output weights −cω² and −2cζω (A.3).
  std::vector<double> dd_, dv_, vd_, vv_;
  std::vector<double> start_d_, start_v_, end_d_, end_v_;
  std::vector<double> out_d_, out_v_;
  std::vector<double> static_d_;  // b/ω² of a quasi-static mode (0 for the others): held still
  double resonant_feedthrough_;   // Σ c_i b_i over the modes that start at rest anyway
  double feedthrough_;  // Σ c_i b_i
  std::vector<double> q_, v_;
  double previous_force_ = 0.0;
  bool started_ = false;
  Start start_ = Start::at_rest;
};

}  // namespace nibrig::model::modal
