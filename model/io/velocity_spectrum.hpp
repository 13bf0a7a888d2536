// The velocity-binned magnitude spectrum of a tool on a surface: the common currency between
// measurement (model/measure), the tool catalog (model/io/catalog), prediction (model/forcing) and
// plots.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace nibrig::model::io {

// amplitude_m_s2[s][f] is the single-sided amplitude (peak, m/s^2) at frequencies_hz[f] while the
// tip moves at speeds_m_s[s]. In JSON files the speeds are written as `speeds_mm_s` (mm/s), see
// catalog_file.hpp.
struct VelocitySpectrum {
  std::vector<double> frequencies_hz;
  std::vector<double> speeds_m_s;
  std::vector<std::vector<double>> amplitude_m_s2;
};

// Whether a and b have the same frequencies and speeds, each to a relative 1e-9 (values that went
// through a file in other units), the speeds also to within `speed_tolerance_m_s` when one is
// given (speeds a recording was segmented into need not match a model's to the last digit).
inline bool same_grid(const VelocitySpectrum& a, const VelocitySpectrum& b,
                      double speed_tolerance_m_s = 0.0) {
  const auto same = [](const std::vector<double>& x, const std::vector<double>& y,
                       double tolerance) {
    if (x.size() != y.size()) return false;
    for (std::size_t k = 0; k < x.size(); ++k)
      if (std::abs(x[k] - y[k]) > std::max(tolerance, 1e-9 * std::max(1.0, std::abs(x[k]))))
        return false;
    return true;
  };
  return same(a.frequencies_hz, b.frequencies_hz, 0.0) &&
         same(a.speeds_m_s, b.speeds_m_s, speed_tolerance_m_s);
}

// The row of `spectrum` whose speed is nearest to v (the first of equally near ones); 0 for a
// spectrum without speeds.
inline std::size_t nearest_speed_row(const VelocitySpectrum& spectrum, double v) {
  std::size_t nearest = 0;
  for (std::size_t m = 0; m < spectrum.speeds_m_s.size(); ++m)
    if (std::abs(spectrum.speeds_m_s[m] - v) < std::abs(spectrum.speeds_m_s[nearest] - v))
      nearest = m;
  return nearest;
}

// `spectrum` at `frequencies_hz` (ascending), each row linearly interpolated between its two
// nearest bins: how a spectrum measured at another resolution (a 48 kHz rig session's 0.67 Hz bins)
// is put on a model's grid (the bundled catalog's 2 Hz), and how a catalog is compacted. Throws
// std::invalid_argument when the spectrum has fewer than two bins or a frequency lies outside its
// range by more than a thousandth of its first bin step.
VelocitySpectrum spectrum_at_frequencies(const VelocitySpectrum& spectrum,
                                         std::span<const double> frequencies_hz);

}  // namespace nibrig::model::io
