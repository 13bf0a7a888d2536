#include "model/modal/frequency_response.hpp"

#include <numbers>
#include <stdexcept>
#include <string>

#include "model/modal/modal_model_checks.hpp"

namespace nibrig::model::modal {

std::vector<double> default_frequency_grid() {
  std::vector<double> grid(500);
  for (std::size_t k = 0; k < grid.size(); ++k) grid[k] = static_cast<double>(k + 1);
  return grid;
}

std::vector<std::complex<double>> frequency_response(const ModalModel& model,
                                                     std::span<const double> frequencies) {
  const std::string caller = "frequency_response";
  check_modal_model(model, caller);
  std::vector<std::complex<double>> h(frequencies.size());
  for (std::size_t k = 0; k < frequencies.size(); ++k) {
    const double f = frequencies[k];
    check_finite(f, "frequency " + std::to_string(k) + " (Hz)", caller);
    if (f < 0.0) {
      throw std::invalid_argument(caller + ": frequency " + std::to_string(k) + " = " +
                                  format_number(f) + " Hz: must be >= 0");
    }
    const double big_omega = 2.0 * std::numbers::pi * f;
    std::complex<double> sum = 0.0;
    for (std::size_t i = 0; i < model.size(); ++i) {
      const double w = model.omega[i];
      // ω² − Ω² factored: near resonance the difference of squares would lose digits.
      const std::complex<double> denominator((w - big_omega) * (w + big_omega),
                                             2.0 * model.zeta[i] * w * big_omega);
      if (denominator == 0.0) {
        throw std::invalid_argument(caller + ": frequency " + format_number(f) +
                                    " Hz is the resonance of undamped mode " + std::to_string(i) +
                                    " (zeta = 0): the response is infinite");
      }
      sum += model.output[i] * model.input[i] * (-big_omega * big_omega) / denominator;
    }
    h[k] = sum;
  }
  return h;
}

std::vector<std::complex<double>> frequency_response(const ModalModel& model) {
  return frequency_response(model, default_frequency_grid());
}

}  // namespace nibrig::model::modal
