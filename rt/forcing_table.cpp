#include "rt/forcing_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <span>
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

// Linear interpolation of (f, a) at the rising points step, 2·step, … out.size()·step, 0 outside
// [f.front(), f.back()]. The points rise, so the segment each falls in is found by walking on, not
// by a search per point: a table has 2^15 to 2^16 bins per speed, and a voice may be built at
// every move of a design slider.
void interpolate_rising(const std::vector<double>& f, const std::vector<double>& a, double step,
                        std::span<double> out) {
  std::size_t after = 0;  // the first frequency above the point's
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double x = static_cast<double>(k + 1) * step;
    if (x < f.front() || x > f.back()) {
      out[k] = 0.0;
      continue;
    }
    while (after < f.size() && f[after] <= x) ++after;
    if (after == f.size()) {
      out[k] = a.back();
      continue;
    }
    const double u = (x - f[after - 1]) / (f[after] - f[after - 1]);
    out[k] = a[after - 1] + u * (a[after] - a[after - 1]);
  }
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
  // A bin k of a real frame carries 2E|X_k|²/N² of the variance; the band it stands for, fs/N,
  // should carry S·fs/N: E|X_k|² = S·fs·N/2 for unit complex noise (E|Z|² = 1). S grows with the
  // square of the mean amplitude, so |X_k| is the amplitude times one factor.
  const double per_amplitude =
      std::sqrt(model::numeric::noise_psd_from_mean_amplitude(1.0, window_seconds) * sample_rate_hz * n / 2.0);
  for (std::size_t s = 0; s < speeds_.size(); ++s) {
    // No DC, no Nyquist bin: bins 1 … N/2 − 1.
    const std::span<double> row(magnitudes_.data() + s * bins() + 1, bins() - 2);
    interpolate_rising(target.frequencies_hz, target.amplitude_m_s2[s], sample_rate_hz / n, row);
    for (double& m : row) m *= per_amplitude;
    for (std::size_t k = bins(); k > active_bins_; --k)
      if (magnitudes_[s * bins() + k - 1] != 0.0) active_bins_ = k;
  }
}

}  // namespace nibrig::rt
