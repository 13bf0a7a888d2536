#include "model/numeric/amplitude_convention.hpp"

#include <cmath>

namespace nibrig::model::numeric {

double noise_psd_from_mean_amplitude(double mean_amplitude, double window_seconds) {
  // E[a]² = (π/4)·2S/T  ⇒  S = 2·T·E[a]²/π
  return 2.0 * window_seconds * mean_amplitude * mean_amplitude / M_PI;
}

double mean_amplitude_from_noise_psd(double psd, double window_seconds) {
  return 0.5 * std::sqrt(M_PI) * std::sqrt(2.0 * psd / window_seconds);
}

}  // namespace nibrig::model::numeric
