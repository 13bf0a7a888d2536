// The exact step of the paper's Eq. 9: one mode driven by a sinusoidal force, advanced over one
// step with no discretisation error, and the offline simulation of a whole ModalModel driven from
// rest by a sum of sinusoids, giving the sensor acceleration (Appendix A.3) at a sample rate.
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

#include "model/modal/modal_model.hpp"
#include "model/modal/modal_oscillator.hpp"

namespace nibrig::model::modal {

// f(t) = amplitude · sin(2π · frequency · t + phase).
struct Sinusoid {
  double amplitude = 0.0;  // N
  double frequency = 0.0;  // Hz, ≥ 0
  double phase = 0.0;      // rad
};

// One mode (ω, ζ) under the unit complex force e^{jΩt} over a step h:
//   x(t+h) = Φ x(t) + e^{jΩ(t+h)} · gain,   gain = ∫_0^h e^{rU} (0, 1)ᵀ e^{−jΩr} dr.
// A real force b·A·sin(Ωt + φ) = Im(b·A·e^{j(Ωt+φ)}) then gives
//   x(t+h) = Φ x(t) + b·A · Im(e^{jθ} gain),   θ = Ω(t+h) + φ,
// which is Eq. 9 written without (Ω² + U²)⁻¹, so it stays finite at the resonance of an undamped
// mode.
struct SinusoidStep {
  Transition transition;
  std::complex<double> displacement_gain;
  std::complex<double> velocity_gain;

  // x(t+h) for the modal force modal_amplitude · sin(Ωτ + φ), given θ = Ω(t+h) + φ.
  ModeState advance(ModeState x, double modal_amplitude, double end_phase) const;
};

// ω > 0, ζ ≥ 0, step > 0, forcing_omega = Ω (rad/s), all finite; not validated here.
SinusoidStep make_sinusoid_step(double omega, double zeta, double step, double forcing_omega);

// 2π · frequency · n / sample_rate reduced to [0, 2π): the reduction happens on the exact product
// frequency · n (exact for integer frequencies below 2^53 / n), so the phase of sample 10⁶ is as
// accurate as that of sample 1.
double sample_phase(double frequency, double sample_rate, std::size_t n);

// Sensor acceleration a(t_n) at t_n = n / sample_rate, n = 0 … samples−1, of the model at rest at
// t = 0 and driven from t = 0 on by Σ_k sinusoids[k] (so a(0) = Σ_i c_i b_i f(0)). Every sample is
// exact up to rounding: there is no time-discretisation error. Throws std::invalid_argument on a
// bad model, sample rate, or a non-finite or negative-frequency sinusoid.
std::vector<double> simulate_sinusoids(const ModalModel& model, std::span<const Sinusoid> sinusoids,
                                       double sample_rate, std::size_t samples);

}  // namespace nibrig::model::modal
