#include "model/modal/response_basis.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/modal/modal_model_checks.hpp"
#include "model/modal/sinusoid_step.hpp"

namespace nibrig::model::modal {

FrequencyResponseBasis::FrequencyResponseBasis(const ModalModel& model, double sample_rate,
                                               std::size_t samples, std::vector<double> frequencies)
    : frequencies_(std::move(frequencies)), sample_rate_(sample_rate), samples_(samples) {
  const std::string caller = "FrequencyResponseBasis";
  check_modal_model(model, caller);
  check_sample_rate(sample_rate, caller);
  for (std::size_t k = 0; k < frequencies_.size(); ++k) {
    check_finite(frequencies_[k], "frequency " + std::to_string(k) + " (Hz)", caller);
    if (frequencies_[k] < 0.0) {
      throw std::invalid_argument(caller + ": frequency " + std::to_string(k) + " = " +
                                  format_number(frequencies_[k]) + " Hz: must be >= 0");
    }
  }

  const std::size_t modes = model.size();
  const double h = 1.0 / sample_rate;
  double feedthrough = 0.0;
  for (std::size_t i = 0; i < modes; ++i) feedthrough += model.output[i] * model.input[i];

  sine_.resize(frequencies_.size() * samples_);
  cosine_.resize(frequencies_.size() * samples_);
  std::vector<SinusoidStep> steps(modes);
  std::vector<std::complex<double>> q(modes), v(modes);
  for (std::size_t k = 0; k < frequencies_.size(); ++k) {
    const double big_omega = 2.0 * std::numbers::pi * frequencies_[k];
    for (std::size_t i = 0; i < modes; ++i) {
      steps[i] = make_sinusoid_step(model.omega[i], model.zeta[i], h, big_omega);
      q[i] = v[i] = 0.0;
    }
    // One complex run drives every mode with e^{jΩt} = cos Ωt + j sin Ωt: by linearity (A.4, A.5)
    // its real part is the cosine response and its imaginary part the sine response.
    for (std::size_t n = 0; n < samples_; ++n) {
      const std::complex<double> e =
          std::polar(1.0, sample_phase(frequencies_[k], sample_rate_, n));
      std::complex<double> a = feedthrough * e;
      for (std::size_t i = 0; i < modes; ++i) {
        if (n > 0) {
          const Transition& t = steps[i].transition;
          const std::complex<double> qn =
              t.dd * q[i] + t.dv * v[i] + model.input[i] * e * steps[i].displacement_gain;
          const std::complex<double> vn =
              t.vd * q[i] + t.vv * v[i] + model.input[i] * e * steps[i].velocity_gain;
          q[i] = qn;
          v[i] = vn;
        }
        const double w = model.omega[i];
        a += model.output[i] * (-w * w * q[i] - 2.0 * model.zeta[i] * w * v[i]);
      }
      cosine_[k * samples_ + n] = a.real();
      sine_[k * samples_ + n] = a.imag();
    }
  }
}

std::span<const double> FrequencyResponseBasis::sine_response(std::size_t k) const {
  if (k >= frequencies_.size()) {
    throw std::out_of_range("FrequencyResponseBasis: frequency index " + std::to_string(k) +
                            " out of range (" + std::to_string(frequencies_.size()) + ")");
  }
  return {sine_.data() + k * samples_, samples_};
}

std::span<const double> FrequencyResponseBasis::cosine_response(std::size_t k) const {
  if (k >= frequencies_.size()) {
    throw std::out_of_range("FrequencyResponseBasis: frequency index " + std::to_string(k) +
                            " out of range (" + std::to_string(frequencies_.size()) + ")");
  }
  return {cosine_.data() + k * samples_, samples_};
}

std::vector<double> FrequencyResponseBasis::synthesize(std::span<const double> amplitudes,
                                                       std::span<const double> phases) const {
  const std::string caller = "FrequencyResponseBasis::synthesize";
  check_same_size(amplitudes.size(), frequencies_.size(), "amplitudes (one per grid frequency)",
                  caller);
  check_same_size(phases.size(), frequencies_.size(), "phases (one per grid frequency)", caller);
  std::vector<double> out(samples_, 0.0);
  for (std::size_t k = 0; k < frequencies_.size(); ++k) {
    check_finite(amplitudes[k], "amplitude " + std::to_string(k) + " (N)", caller);
    check_finite(phases[k], "phase " + std::to_string(k) + " (rad)", caller);
    if (amplitudes[k] == 0.0) continue;
    const double ws = amplitudes[k] * std::cos(phases[k]);
    const double wc = amplitudes[k] * std::sin(phases[k]);
    const double* s = sine_.data() + k * samples_;
    const double* c = cosine_.data() + k * samples_;
    for (std::size_t n = 0; n < samples_; ++n) out[n] += ws * s[n] + wc * c[n];
  }
  return out;
}

}  // namespace nibrig::model::modal
