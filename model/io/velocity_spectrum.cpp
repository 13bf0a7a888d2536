#include "model/io/velocity_spectrum.hpp"

#include <sstream>
#include <stdexcept>

namespace nibrig::model::io {

VelocitySpectrum spectrum_at_frequencies(const VelocitySpectrum& spectrum,
                                         std::span<const double> frequencies_hz) {
  const auto& f = spectrum.frequencies_hz;
  if (f.size() < 2)
    throw std::invalid_argument("a spectrum of fewer than two bins cannot be interpolated");
  const double slack = 1e-3 * (f[1] - f[0]);
  VelocitySpectrum out;
  out.frequencies_hz.assign(frequencies_hz.begin(), frequencies_hz.end());
  out.speeds_m_s = spectrum.speeds_m_s;
  for (double x : frequencies_hz)
    if (!(x >= f.front() - slack && x <= f.back() + slack)) {
      std::ostringstream message;
      message << "frequency " << x << " Hz lies outside the spectrum's " << f.front() << "-"
              << f.back() << " Hz";
      throw std::invalid_argument(message.str());
    }
  for (const auto& row : spectrum.amplitude_m_s2) {
    std::vector<double> at;
    at.reserve(frequencies_hz.size());
    for (double x : frequencies_hz) {
      // The bin pair around x; a frequency within the slack beyond an end takes that end's value.
      const auto upper = std::lower_bound(f.begin(), f.end(), x);
      if (upper == f.begin()) {
        at.push_back(row.front());
        continue;
      }
      if (upper == f.end()) {
        at.push_back(row.back());
        continue;
      }
      const auto i = static_cast<std::size_t>(upper - f.begin());
      const double t = (x - f[i - 1]) / (f[i] - f[i - 1]);
      at.push_back(row[i - 1] + t * (row[i] - row[i - 1]));
    }
    out.amplitude_m_s2.push_back(std::move(at));
  }
  return out;
}

}  // namespace nibrig::model::io
