#include "model/measure/velocity_binning.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace nibrig::model::measure {

std::vector<double> smooth_shrinking_span(std::span<const double> values, std::size_t span) {
  if (span == 0) throw std::invalid_argument("smoothing span must be at least 1");
  // MATLAB's smooth() makes an even span odd by dropping one.
  const std::size_t half = (span % 2 == 0 ? span - 1 : span) / 2;
  const std::size_t n = values.size();
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t h = std::min({half, i, n - 1 - i});
    double sum = 0.0;
    for (std::size_t j = i - h; j <= i + h; ++j) sum += values[j];
    out[i] = sum / static_cast<double>(2 * h + 1);
  }
  return out;
}

namespace {

void check_rate(double rate, const char* what) {
  if (!(rate > 0.0) || !std::isfinite(rate)) {
    throw std::invalid_argument(std::string(what) + " must be positive and finite");
  }
}

// Indices of the bins kept by the settings' half-open frequency range.
std::vector<std::size_t> kept_bins(const std::vector<double>& frequencies,
                                   const BinningSettings& settings) {
  if (!(settings.max_frequency_hz > settings.min_frequency_hz)) {
    throw std::invalid_argument("binning: max_frequency_hz must exceed min_frequency_hz");
  }
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < frequencies.size(); ++k) {
    // A relative tolerance keeps bins that sit exactly on the lower limit (6.000 Hz = 9·1000/1500).
    const double f = frequencies[k];
    const double tol = 1e-9 * std::max(1.0, std::abs(f));
    if (f >= settings.min_frequency_hz - tol && f < settings.max_frequency_hz - tol) {
      kept.push_back(k);
    }
  }
  if (kept.empty()) throw std::invalid_argument("binning: no frequency bin in the requested range");
  return kept;
}

// Crops one spectrum row to the kept bins and smooths it.
std::vector<double> crop_and_smooth(std::span<const double> row,
                                    const std::vector<std::size_t>& kept, std::size_t smoothing) {
  std::vector<double> cropped(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) cropped[i] = row[kept[i]];
  return smoothing > 1 ? smooth_shrinking_span(cropped, smoothing) : cropped;
}

}  // namespace

io::VelocitySpectrum spectrum_per_step(std::span<const double> x, double fs,
                                       const StepSegmentation& segmentation,
                                       const BinningSettings& settings) {
  check_rate(fs, "sample rate");
  const auto& steps = segmentation.steps;
  if (steps.empty()) throw std::invalid_argument("spectrum_per_step: no steps");
  const std::size_t length = steps.front().end - steps.front().begin;
  for (const SpeedStep& s : steps) {
    if (s.end <= s.begin || s.end - s.begin != length || s.end > x.size()) {
      throw std::invalid_argument("spectrum_per_step: step windows must have one length (" +
                                  std::to_string(length) + " samples) inside the signal (" +
                                  std::to_string(x.size()) + " samples)");
    }
  }
  SpectrumAnalyzer analyzer(length, settings.window);
  std::vector<double> frequencies(analyzer.bins());
  for (std::size_t k = 0; k < frequencies.size(); ++k) {
    frequencies[k] = analyzer.bin_frequency_hz(k, fs);
  }
  const std::vector<std::size_t> kept = kept_bins(frequencies, settings);

  // Sum spectra per distinct speed (exact equality: the speeds come from one protocol table).
  std::vector<double> speeds;
  std::vector<std::vector<double>> sums;
  std::vector<std::size_t> counts;
  std::vector<double> amplitude(analyzer.bins());
  for (const SpeedStep& s : steps) {
    analyzer.amplitude(x.subspan(s.begin, length), amplitude, true);
    auto it = std::find(speeds.begin(), speeds.end(), s.speed_m_s);
    std::size_t row = static_cast<std::size_t>(it - speeds.begin());
    if (it == speeds.end()) {
      speeds.push_back(s.speed_m_s);
      sums.emplace_back(analyzer.bins(), 0.0);
      counts.push_back(0);
    }
    for (std::size_t k = 0; k < amplitude.size(); ++k) sums[row][k] += amplitude[k];
    ++counts[row];
  }

  io::VelocitySpectrum result;
  for (std::size_t k : kept) result.frequencies_hz.push_back(frequencies[k]);
  result.speeds_m_s = speeds;
  for (std::size_t r = 0; r < speeds.size(); ++r) {
    for (double& v : sums[r]) v /= static_cast<double>(counts[r]);
    result.amplitude_m_s2.push_back(crop_and_smooth(sums[r], kept, settings.smoothing_bins));
  }
  return result;
}

io::VelocitySpectrum spectrum_by_speed(std::span<const double> acceleration,
                                       double acceleration_rate_hz,
                                       std::span<const double> speed_m_s, double speed_rate_hz,
                                       std::span<const double> edges,
                                       const SpectrogramSettings& spectrogram_settings,
                                       const BinningSettings& settings,
                                       SpeedBinningReport* report) {
  check_rate(acceleration_rate_hz, "acceleration rate");
  check_rate(speed_rate_hz, "speed rate");
  if (edges.size() < 2) throw std::invalid_argument("spectrum_by_speed: need at least 2 bin edges");
  for (std::size_t b = 0; b + 1 < edges.size(); ++b) {
    if (!(edges[b + 1] > edges[b])) {
      throw std::invalid_argument("spectrum_by_speed: bin edges must increase strictly");
    }
  }
  if (speed_m_s.empty()) throw std::invalid_argument("spectrum_by_speed: empty speed signal");

  const Spectrogram sg =
      compute_spectrogram(acceleration, acceleration_rate_hz, spectrogram_settings);
  const std::vector<std::size_t> kept = kept_bins(sg.frequencies_hz, settings);
  const std::size_t bins = edges.size() - 1;
  const auto columns = sg.amplitude.cols();

  SpeedBinningReport local;
  local.segments_per_bin.assign(bins, 0);
  std::vector<std::vector<double>> sums(
      bins, std::vector<double>(static_cast<std::size_t>(columns), 0.0));
  std::vector<double> speed_sums(bins, 0.0);
  const double last_time = static_cast<double>(speed_m_s.size() - 1) / speed_rate_hz;
  for (std::size_t i = 0; i < sg.times_s.size(); ++i) {
    const double t = sg.times_s[i];
    if (t < 0.0 || t > last_time) {
      ++local.segments_outside_speed_record;
      continue;
    }
    const double pos = t * speed_rate_hz;
    const auto i0 = std::min(static_cast<std::size_t>(pos), speed_m_s.size() - 1);
    const std::size_t i1 = std::min(i0 + 1, speed_m_s.size() - 1);
    const double frac = pos - static_cast<double>(i0);
    const double v = speed_m_s[i0] + frac * (speed_m_s[i1] - speed_m_s[i0]);
    if (v < edges.front() || v > edges.back()) {
      ++local.segments_outside_bins;
      continue;
    }
    auto upper = std::upper_bound(edges.begin(), edges.end(), v);
    std::size_t b = static_cast<std::size_t>(upper - edges.begin());
    b = b == 0 ? 0 : std::min(b - 1, bins - 1);  // v == last edge belongs to the last bin
    ++local.segments_per_bin[b];
    speed_sums[b] += v;
    const auto row = sg.amplitude.row(static_cast<Eigen::Index>(i));
    for (Eigen::Index k = 0; k < columns; ++k) sums[b][static_cast<std::size_t>(k)] += row(k);
  }

  io::VelocitySpectrum result;
  for (std::size_t k : kept) result.frequencies_hz.push_back(sg.frequencies_hz[k]);
  for (std::size_t b = 0; b < bins; ++b) {
    const std::size_t n = local.segments_per_bin[b];
    if (n == 0) {
      local.empty_bins.push_back(b);
      spdlog::warn("speed bin [{:.4f}, {:.4f}] m/s holds no spectrogram segment: dropped", edges[b],
                   edges[b + 1]);
      continue;
    }
    for (double& a : sums[b]) a /= static_cast<double>(n);
    result.speeds_m_s.push_back(speed_sums[b] / static_cast<double>(n));
    result.amplitude_m_s2.push_back(crop_and_smooth(sums[b], kept, settings.smoothing_bins));
  }
  if (local.segments_outside_speed_record > 0) {
    spdlog::warn("{} spectrogram segments lie outside the speed record and were not used",
                 local.segments_outside_speed_record);
  }
  if (local.segments_outside_bins > 0) {
    spdlog::warn(
        "{} spectrogram segments have speeds outside [{:.4f}, {:.4f}] m/s and were not used",
        local.segments_outside_bins, edges.front(), edges.back());
  }
  if (report != nullptr) *report = local;
  if (result.speeds_m_s.empty()) {
    throw std::runtime_error("spectrum_by_speed: no spectrogram segment falls in any speed bin");
  }
  return result;
}

}  // namespace nibrig::model::measure
