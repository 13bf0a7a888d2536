#include "model/modal/sinusoid_step.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "model/modal/modal_model_checks.hpp"

// Derivation of Eq. 9 (the paper's typesetting drops a parenthesis and misplaces φ). For one mode,
// X = (q, q̇), Ẋ = UX + (0, 1)ᵀ F(t), the variation-of-constants formula (Eq. 8) over one step is
//   X(t+h) = e^{hU} X(t) + ∫_0^h e^{rU} (0, 1)ᵀ F(t + h − r) dr.
// With F(τ) = e^{jΩτ} the integrand factors: F(t+h−r) = e^{jΩ(t+h)} e^{−jΩr}, hence the gain above.
// Its components are moments of the impulse response g (e^{rU}(0,1)ᵀ = (g, g')):
//   displacement: ∫ g e^{−jΩr} dr = M₀(−Ω)
//   velocity:     ∫ g' e^{−jΩr} dr = g(h) e^{−jΩh} + jΩ M₀(−Ω)      (by parts, g(0) = 0).
// The paper's closed form, X(t+h) = e^{hU}(X(t) − X_p(t)) + X_p(t+h) with the steady state
// X_p(τ) = −(Ω² + U²)⁻¹ (U sin(Ωτ+φ) + Ω cos(Ωτ+φ)) (0, 1)ᵀ A, is the same number; expanding it
// gives
//   X(t+h) = e^{hU}X(t) + (Ω²+U²)⁻¹ [ e^{hU}(Ω cos(Ωt+φ) + U sin(Ωt+φ))
//                                     − Ω cos(Ω(t+h)+φ) − U sin(Ω(t+h)+φ) ] (0, 1)ᵀ A,
// but it divides by Ω² + U², which is singular at the resonance of an undamped mode, and it
// subtracts two steady states of equal size from a small transient; the moments do neither.

namespace nibrig::model::modal {

ModeState SinusoidStep::advance(ModeState x, double modal_amplitude, double end_phase) const {
  // Not std::polar(modal_amplitude, …): the amplitude carries the sign of b and may be negative.
  const std::complex<double> e = modal_amplitude * std::polar(1.0, end_phase);
  const ModeState free = transition.apply(x);
  return {free.displacement + (e * displacement_gain).imag(),
          free.velocity + (e * velocity_gain).imag()};
}

SinusoidStep make_sinusoid_step(double omega, double zeta, double step, double forcing_omega) {
  SinusoidStep s;
  s.transition = mode_transition(omega, zeta, step);
  // M₀(−Ω) = conj(M₀(Ω)) because g is real; computed directly with −Ω.
  const std::complex<double> m0 = impulse_response_moment(omega, zeta, step, 0, -forcing_omega);
  const std::complex<double> j_omega(0.0, forcing_omega);
  s.displacement_gain = m0;
  s.velocity_gain = s.transition.dv * std::polar(1.0, -forcing_omega * step) + j_omega * m0;
  return s;
}

double sample_phase(double frequency, double sample_rate, std::size_t n) {
  const double cycles = std::fmod(frequency * static_cast<double>(n), sample_rate) / sample_rate;
  return 2.0 * std::numbers::pi * cycles;
}

std::vector<double> simulate_sinusoids(const ModalModel& model, std::span<const Sinusoid> sinusoids,
                                       double sample_rate, std::size_t samples) {
  const std::string caller = "simulate_sinusoids";
  check_modal_model(model, caller);
  check_sample_rate(sample_rate, caller);
  for (std::size_t k = 0; k < sinusoids.size(); ++k) {
    const std::string name = "sinusoid " + std::to_string(k);
    check_finite(sinusoids[k].amplitude, name + " amplitude (N)", caller);
    check_finite(sinusoids[k].frequency, name + " frequency (Hz)", caller);
    check_finite(sinusoids[k].phase, name + " phase (rad)", caller);
    if (sinusoids[k].frequency < 0.0) {
      throw std::invalid_argument(caller + ": " + name + " frequency " +
                                  format_number(sinusoids[k].frequency) + " Hz: must be >= 0");
    }
  }

  const std::size_t modes = model.size();
  const std::size_t count = sinusoids.size();
  const double h = 1.0 / sample_rate;

  std::vector<Transition> transitions(modes);
  // gain[i·count + k] already carries b_i · A_k, so the per-sample work is one complex product.
  std::vector<std::complex<double>> gain_d(modes * count), gain_v(modes * count);
  double feedthrough = 0.0;  // Σ c_i b_i: the part of a(t) that follows f(t) instantly
  for (std::size_t i = 0; i < modes; ++i) {
    feedthrough += model.output[i] * model.input[i];
    transitions[i] = mode_transition(model.omega[i], model.zeta[i], h);
    for (std::size_t k = 0; k < count; ++k) {
      const double big_omega = 2.0 * std::numbers::pi * sinusoids[k].frequency;
      const SinusoidStep s = make_sinusoid_step(model.omega[i], model.zeta[i], h, big_omega);
      const double scale = model.input[i] * sinusoids[k].amplitude;
      gain_d[i * count + k] = scale * s.displacement_gain;
      gain_v[i * count + k] = scale * s.velocity_gain;
    }
  }

  std::vector<double> acceleration(samples);
  std::vector<ModeState> x(modes);  // at rest at t = 0
  std::vector<std::complex<double>> phasor(count);
  for (std::size_t n = 0; n < samples; ++n) {
    double force = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
      phasor[k] = std::polar(
          1.0, sample_phase(sinusoids[k].frequency, sample_rate, n) + sinusoids[k].phase);
      force += sinusoids[k].amplitude * phasor[k].imag();
    }
    double a = feedthrough * force;
    for (std::size_t i = 0; i < modes; ++i) {
      if (n > 0) {
        ModeState next = transitions[i].apply(x[i]);
        for (std::size_t k = 0; k < count; ++k) {
          next.displacement += (phasor[k] * gain_d[i * count + k]).imag();
          next.velocity += (phasor[k] * gain_v[i * count + k]).imag();
        }
        x[i] = next;
      }
      a += model.output[i] * modal_acceleration(model.omega[i], model.zeta[i], x[i], 0.0);
    }
    acceleration[n] = a;
  }
  return acceleration;
}

}  // namespace nibrig::model::modal
