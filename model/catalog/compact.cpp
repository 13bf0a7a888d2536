#include "model/catalog/compact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nibrig::model::catalog {

io::VelocitySpectrum resample_spectrum(const io::VelocitySpectrum& spectrum,
                                       double frequency_step_hz) {
  const auto& f = spectrum.frequencies_hz;
  if (!(frequency_step_hz > 0.0)) throw std::invalid_argument("frequency step must be positive");
  if (f.size() < 2) return spectrum;
  std::vector<double> grid;
  const double first = std::ceil(f.front() / frequency_step_hz) * frequency_step_hz;
  for (double x = first; x <= f.back() + 1e-9; x += frequency_step_hz) grid.push_back(x);
  return io::spectrum_at_frequencies(spectrum, grid);
}

double round_significant(double value, int digits) {
  if (value == 0.0 || !std::isfinite(value)) return value;
  const double magnitude = std::floor(std::log10(std::fabs(value)));
  const double scale = std::pow(10.0, static_cast<double>(digits) - 1.0 - magnitude);
  return std::round(value * scale) / scale;
}

io::Catalog compact_catalog(io::Catalog catalog, double frequency_step_hz, int significant_digits) {
  for (auto& pairing : catalog.pairings) {
    if (!pairing.vibration) continue;
    auto& spectrum = pairing.vibration->spectrum;
    spectrum = resample_spectrum(spectrum, frequency_step_hz);
    for (auto& row : spectrum.amplitude_m_s2) {
      for (double& a : row) a = round_significant(a, significant_digits);
    }
    pairing.vibration->provenance.method +=
        "; resampled to " + std::to_string(frequency_step_hz) + " Hz steps and rounded to " +
        std::to_string(significant_digits) + " significant digits for bundling";
  }
  return catalog;
}

}  // namespace nibrig::model::catalog
