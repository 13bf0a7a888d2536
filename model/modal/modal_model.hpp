// A stylus reduced to its modes: what the integrator, the frequency response and (later) the
// real-time voice need. Each mode i is an independent damped oscillator
//   q̈_i + 2 ζ_i ω_i q̇_i + ω_i² q_i = b_i f(t),   output a(t) = Σ_i c_i q̈_i(t)
// where f is the force at the tip along the tip direction (N), b_i = φ_i(tip)·direction and
// c_i = φ_i(sensor)·axis for mass-normalised mode shapes φ_i, so a is the acceleration (m/s²) at
// the sensor along its axis.
#pragma once

#include <vector>

namespace nibrig::model::modal {

struct ModalModel {
  std::vector<double> omega;  // undamped angular frequency ω_i, rad/s, ascending, > 0
  std::vector<double> zeta;   // damping ratio ζ_i ≥ 0 (may exceed 1: overdamped modes are valid)
  std::vector<double> input;  // b_i = φ_i(tip)·direction, kg^-½ (φ_iᵀ M φ_i = 1)
  std::vector<double> output;  // c_i = φ_i(sensor)·axis, kg^-½

  std::size_t size() const { return omega.size(); }
};

// Rayleigh damping D = αM + λK gives ζ_i = α/(2ω_i) + λω_i/2 (the paper uses α = 0).
inline double rayleigh_damping_ratio(double omega, double mass_coefficient,
                                     double stiffness_coefficient) {
  return mass_coefficient / (2.0 * omega) + stiffness_coefficient * omega / 2.0;
}

}  // namespace nibrig::model::modal
