#include "model/forcing/measured_forcing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/modal/frequency_response.hpp"

namespace nibrig::model::forcing {

io::VelocitySpectrum forcing_from_acceleration(const io::VelocitySpectrum& acceleration,
                                               const modal::ModalModel& model,
                                               double regularisation) {
  if (!(regularisation >= 0) || !std::isfinite(regularisation))
    throw std::invalid_argument("the regularisation must be finite and >= 0");
  const auto h = modal::frequency_response(model, acceleration.frequencies_hz);
  double peak = 0;
  for (const auto& x : h) peak = std::max(peak, std::abs(x));
  const double floor = regularisation * peak;
  io::VelocitySpectrum forcing = acceleration;
  for (auto& row : forcing.amplitude_m_s2)
    for (std::size_t k = 0; k < row.size(); ++k) {
      const double magnitude = std::abs(h[k]);
      const double denominator = magnitude * magnitude + floor * floor;
      row[k] = denominator > 0 ? row[k] * magnitude / denominator : 0.0;
    }
  return forcing;
}

}  // namespace nibrig::model::forcing
