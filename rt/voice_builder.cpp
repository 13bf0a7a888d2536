#include "rt/voice_builder.hpp"

#include <algorithm>
#include <cmath>

#include "model/modal/discrete_frequency_response.hpp"

namespace nibrig::rt {

std::unique_ptr<Voice> build_voice(std::string name, const model::modal::ModalModel& modal,
                                   const model::io::VelocitySpectrum& acceleration,
                                   double internal_rate_hz, std::uint64_t seed,
                                   double regularisation) {
  const auto h = model::modal::discrete_frequency_response(modal, internal_rate_hz,
                                                           acceleration.frequencies_hz);
  double peak = 0;
  for (const auto& x : h) peak = std::max(peak, std::abs(x));
  const double floor = regularisation * peak;
  model::io::VelocitySpectrum forcing = acceleration;
  for (auto& row : forcing.amplitude_m_s2)
    for (std::size_t k = 0; k < row.size(); ++k) {
      const double m = std::abs(h[k]);
      const double denominator = m * m + floor * floor;
      row[k] = denominator > 0 ? row[k] * m / denominator : 0.0;
    }
  auto table = std::make_shared<const ForcingTable>(forcing, internal_rate_hz);
  return std::make_unique<Voice>(std::move(name), modal, std::move(table), seed);
}

}  // namespace nibrig::rt
