// The streaming integrator of a whole ModalModel under a sampled force, joined linearly between
// samples (exact for that force): a two-pole recursion per mode, the modes' state and coefficients
// preallocated in groups of four (a vector register each), and a process() that neither
// allocates, locks nor throws, for rt/ to run on the audio thread. Everything that can fail
// happens in the constructor.
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
  double displacement(std::size_t mode) const noexcept {
    return groups_[mode / kLanes].q[mode % kLanes];
  }
  double velocity(std::size_t mode) const noexcept {
    return groups_[mode / kLanes].v[mode % kLanes];
  }

  // For each n: takes f(t_n) = force[n] (N), advances the modes from t_{n−1} (force linear in
  // between) and writes the sensor acceleration a(t_n) (m/s²). force and acceleration may be the
  // same buffer. Real-time safe: no allocation, lock or exception; cost 11 multiply-adds per mode
  // per sample. The state is double whatever the buffers. Decaying modes reach subnormal numbers
  // after a long silence: the caller (rt/) runs with flush-to-zero set.
  void process(const float* force, float* acceleration, std::size_t count) noexcept;
  void process(const double* force, double* acceleration, std::size_t count) noexcept;

  // The loop that runs the modes: the portable one, or the same compiled for AVX2 and FMA, chosen
  // at construction when this CPU has them (bench_integrator.cpp times both). A fused
  // multiply-add rounds once where the portable loop rounds twice, so the two agree to rounding,
  // not bit for bit. set_kernel is for comparing them: it throws std::invalid_argument for
  // avx2_fma on a CPU without them. Not for the audio thread.
  enum class Kernel { portable, avx2_fma };
  Kernel kernel() const noexcept { return kernel_; }
  void set_kernel(Kernel kernel);

  // Four modes side by side, each row one register of the vector loop: their state q, v; Φ;
  // Γ₀ and Γ₁ scaled by b (from the force at the step's start and end); and the output weights
  // −cω² and −2cζω (A.3). A last group is padded with modes that are zero throughout.
  static constexpr std::size_t kLanes = 4;
  struct alignas(kLanes * sizeof(double)) ModeGroup {
    double q[kLanes], v[kLanes];
    double dd[kLanes], dv[kLanes], vd[kLanes], vv[kLanes];
    double sd[kLanes], sv[kLanes], ed[kLanes], ev[kLanes];
    double od[kLanes], ov[kLanes];
  };

 private:
  template <class Sample>
  void run(const Sample* force, Sample* acceleration, std::size_t count) noexcept;

  std::size_t modes_;
  double sample_rate_;
  std::vector<ModeGroup> groups_;
  std::vector<double> static_d_;  // b/ω² of a quasi-static mode (0 for the others): held still
  double resonant_feedthrough_;   // Σ c_i b_i over the modes that start at rest anyway
  double feedthrough_;            // Σ c_i b_i
  double previous_force_ = 0.0;
  bool started_ = false;
  Start start_ = Start::at_rest;
  Kernel kernel_;
};

}  // namespace nibrig::model::modal
