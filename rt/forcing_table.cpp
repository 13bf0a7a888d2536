#include "rt/forcing_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace nibrig::rt {
namespace {

void check(const model::io::VelocitySpectrum& t, double sample_rate_hz, double window_seconds) {
  if (!(sample_rate_hz > 0) || !std::isfinite(sample_rate_hz))
    throw std::invalid_argument("a forcing table needs a positive sample rate");
  if (!(window_seconds > 0) || !std::isfinite(window_seconds))
    throw std::invalid_argument("a forcing table needs a positive analysis window");
  const auto& f = t.frequencies_hz;
  if (f.size() < 2) throw std::invalid_argument("a forcing spectrum needs at least 2 frequencies");
  if (t.speeds_m_s.empty()) throw std::invalid_argument("a forcing spectrum needs a speed");
  if (t.amplitude_m_s2.size() != t.speeds_m_s.size())
    throw std::invalid_argument("a forcing spectrum needs one amplitude row per speed");
  for (std::size_t i = 0; i < f.size(); ++i)
    if (!std::isfinite(f[i]) || f[i] < 0 || (i > 0 && !(f[i] > f[i - 1])))
      throw std::invalid_argument("forcing frequencies must be finite, >= 0 and increasing");
  if (!(f.back() < sample_rate_hz / 2))
    throw std::invalid_argument("the forcing spectrum reaches " + std::to_string(f.back()) +
                                " Hz, at or above the Nyquist frequency of " +
                                std::to_string(sample_rate_hz / 2) + " Hz");
  for (std::size_t s = 0; s < t.speeds_m_s.size(); ++s) {
    const double v = t.speeds_m_s[s];
    if (!(v > 0) || !std::isfinite(v) || (s > 0 && !(v > t.speeds_m_s[s - 1])))
      throw std::invalid_argument("forcing speeds must be positive and increasing");
    if (t.amplitude_m_s2[s].size() != f.size())
      throw std::invalid_argument("forcing row " + std::to_string(s) + " has " +
                                  std::to_string(t.amplitude_m_s2[s].size()) +
                                  " values for " + std::to_string(f.size()) + " frequencies");
    for (double a : t.amplitude_m_s2[s])
      if (!(a >= 0) || !std::isfinite(a))
        throw std::invalid_argument("forcing amplitudes must be finite and >= 0");
  }
}

// Linear interpolation inside [f.front(), f.back()], 0 outside.
double amplitude_at(const std::vector<double>& f, const std::vector<double>& a, double x) {
  if (x < f.front() || x > f.back()) return 0.0;
  const auto after = std::upper_bound(f.begin(), f.end(), x);
  if (after == f.end()) return a.back();
  const auto i = static_cast<std::size_t>(after - f.begin());
  const double u = (x - f[i - 1]) / (f[i] - f[i - 1]);
  return a[i - 1] + u * (a[i] - a[i - 1]);
}

}  // namespace

ForcingTable::ForcingTable(const model::io::VelocitySpectrum& target, double sample_rate_hz,
                           double window_seconds)
    : sample_rate_(sample_rate_hz), frame_length_(2) {
  check(target, sample_rate_hz, window_seconds);
  while (static_cast<double>(frame_length_) < sample_rate_hz) frame_length_ *= 2;
  speeds_ = target.speeds_m_s;
  magnitudes_.assign(speeds_.size() * bins(), 0.0);
  const double n = static_cast<double>(frame_length_);
  for (std::size_t s = 0; s < speeds_.size(); ++s) {
    for (std::size_t k = 1; k + 1 < bins(); ++k) {  // no DC, no Nyquist bin
      const double f = static_cast<double>(k) * sample_rate_hz / n;
      const double a = amplitude_at(target.frequencies_hz, target.amplitude_m_s2[s], f);
      const double psd = model::numeric::noise_psd_from_mean_amplitude(a, window_seconds);
      // A bin k of a real frame carries 2E|X_k|²/N² of the variance; the band it stands for,
      // fs/N, should carry S·fs/N: E|X_k|² = S·fs·N/2 for unit complex noise (E|Z|² = 1).
      magnitudes_[s * bins() + k] = std::sqrt(psd * sample_rate_hz * n / 2.0);
    }
  }
}

}  // namespace nibrig::rt
