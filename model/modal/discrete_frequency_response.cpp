#include "model/modal/discrete_frequency_response.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "model/modal/linear_forcing_step.hpp"
#include "model/modal/modal_model_checks.hpp"

namespace nibrig::model::modal {

std::vector<std::complex<double>> discrete_frequency_response(const ModalModel& model,
                                                              double sample_rate_hz,
                                                              std::span<const double> frequencies) {
  const std::string caller = "discrete_frequency_response";
  check_modal_model(model, caller);
  check_sample_rate(sample_rate_hz, caller);
  const double h = 1.0 / sample_rate_hz;
  // z⁻¹ = e^{−j2πf h} once per frequency, not once per mode: a voice may be built at every slider
  // move, and the sine and cosine were most of its cost.
  std::vector<std::complex<double>> delay(frequencies.size());
  for (std::size_t k = 0; k < frequencies.size(); ++k) {
    const double f = frequencies[k];
    if (!(f >= 0) || !(f <= sample_rate_hz / 2))
      throw std::invalid_argument(caller + ": frequency " + format_number(f) + " Hz is outside [0, fs/2]");
    delay[k] = std::polar(1.0, -2.0 * std::numbers::pi * f * h);
  }
  std::vector<std::complex<double>> response(frequencies.size(), 0.0);
  for (std::size_t i = 0; i < model.size(); ++i) {
    const double w = model.omega[i], zeta = model.zeta[i], b = model.input[i], c = model.output[i];
    const LinearForcingStep step = make_linear_forcing_step(w, zeta, h);
    const Transition& phi = step.transition;
    for (std::size_t k = 0; k < frequencies.size(); ++k) {
      // X(z) = (I − Φ z⁻¹)⁻¹ b (Γ₀ z⁻¹ + Γ₁) F(z).
      const std::complex<double> zi = delay[k];
      const std::complex<double> m00 = 1.0 - phi.dd * zi, m01 = -phi.dv * zi,
                                 m10 = -phi.vd * zi, m11 = 1.0 - phi.vv * zi;
      const std::complex<double> rd = b * (step.from_start.displacement * zi + step.from_end.displacement);
      const std::complex<double> rv = b * (step.from_start.velocity * zi + step.from_end.velocity);
      // 1/det as conj/|det|²: det is near 1 in size (|Φ| < 1), so the scaling that the library's
      // complex division does against overflow buys nothing and cost a fifth of the response.
      const std::complex<double> det = m00 * m11 - m01 * m10;
      const std::complex<double> inverse_det = std::conj(det) / std::norm(det);
      const std::complex<double> q = (m11 * rd - m01 * rv) * inverse_det;
      const std::complex<double> v = (-m10 * rd + m00 * rv) * inverse_det;
      response[k] += c * (-w * w * q - 2.0 * zeta * w * v + b);
    }
  }
  return response;
}

}  // namespace nibrig::model::modal
