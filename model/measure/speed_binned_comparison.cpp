#include "model/measure/speed_binned_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/io/velocity_spectrum.hpp"
#include "model/measure/descriptors.hpp"

namespace nibrig::model::measure {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A one-speed spectrum of the band, which compute_vibration_descriptors weighs as it weighs a
// catalog entry.
double weighted_mean_of(const std::vector<double>& frequencies, std::span<const double> band,
                        double speed, const ThresholdCurve& threshold) {
  io::VelocitySpectrum spectrum{frequencies, {speed}, {{band.begin(), band.end()}}};
  return compute_vibration_descriptors(spectrum, threshold, 1).weighted_mean;
}

}  // namespace

std::vector<double> geometric_speed_edges(double min_speed_m_s, double max_speed_m_s,
                                          std::size_t speed_bins) {
  if (speed_bins == 0) throw std::invalid_argument("speed bins: need at least one bin");
  if (!(min_speed_m_s > 0.0) || !(max_speed_m_s > min_speed_m_s) || !std::isfinite(max_speed_m_s))
    throw std::invalid_argument("speed bins: need 0 < min < max, finite; got " +
                                std::to_string(min_speed_m_s) + " to " +
                                std::to_string(max_speed_m_s) + " m/s");
  std::vector<double> edges(speed_bins + 1);
  const double ratio = max_speed_m_s / min_speed_m_s;
  for (std::size_t b = 0; b <= speed_bins; ++b)
    edges[b] =
        min_speed_m_s * std::pow(ratio, static_cast<double>(b) / static_cast<double>(speed_bins));
  edges.front() = min_speed_m_s;  // exact ends, whatever pow rounds to
  edges.back() = max_speed_m_s;
  return edges;
}

SampleRange speed_samples_of_span(std::uint64_t first_sample, std::size_t length, double rate_hz,
                                  double speed_rate_hz) {
  // ceil(n · speed_rate / rate): the first speed sample at or after acceleration sample n. The
  // small allowance keeps a product that should be an integer (48 kHz against 1 kHz) from
  // rounding up past it.
  const auto first_at_or_after = [&](std::uint64_t n) {
    return static_cast<std::uint64_t>(
        std::ceil(static_cast<double>(n) * speed_rate_hz / rate_hz - 1e-9));
  };
  SampleRange r{first_at_or_after(first_sample), first_at_or_after(first_sample + length)};
  if (r.end <= r.begin) r.end = r.begin + 1;
  return r;
}

double log_spectral_distance_db(std::span<const double> measured,
                                std::span<const double> simulated) {
  if (measured.size() != simulated.size()) return kNaN;
  const double db = 20.0 / std::log(10.0);
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t k = 0; k < measured.size(); ++k) {
    if (!(measured[k] > 0 && simulated[k] > 0)) continue;
    const double d = db * std::log(simulated[k] / measured[k]);
    sum += d * d;
    ++count;
  }
  return count > 0 ? std::sqrt(sum / static_cast<double>(count)) : kNaN;
}

SpeedBinnedComparison::SpeedBinnedComparison(std::vector<double> frequencies_hz,
                                             const SpeedBinnedComparisonSettings& settings,
                                             ThresholdCurve threshold)
    : frequencies_(std::move(frequencies_hz)),
      edges_(geometric_speed_edges(settings.min_speed_m_s, settings.max_speed_m_s,
                                   settings.speed_bins)),
      threshold_(std::move(threshold)) {
  if (frequencies_.size() < 2)
    throw std::invalid_argument("speed-binned comparison: need at least two frequencies");
  // Half-open band, as BinningSettings crops the catalog's spectra.
  band_first_ = static_cast<std::size_t>(
      std::lower_bound(frequencies_.begin(), frequencies_.end(), settings.min_frequency_hz) -
      frequencies_.begin());
  band_last_ = static_cast<std::size_t>(
      std::lower_bound(frequencies_.begin(), frequencies_.end(), settings.max_frequency_hz) -
      frequencies_.begin());
  if (band_last_ < band_first_ + 2)
    throw std::invalid_argument(
        "speed-binned comparison: the band " + std::to_string(settings.min_frequency_hz) + " to " +
        std::to_string(settings.max_frequency_hz) + " Hz holds fewer than two of the " +
        std::to_string(frequencies_.size()) + " frequencies (spacing " +
        std::to_string(frequencies_[1] - frequencies_[0]) + " Hz): use longer segments");
  const std::size_t bins = speed_bins();
  counts_.assign(bins, 0);
  speed_sums_.assign(bins, 0.0);
  measured_sums_.assign(bins * frequencies_.size(), 0.0);
  simulated_sums_.assign(bins * frequencies_.size(), 0.0);
}

std::size_t SpeedBinnedComparison::bin_of(double speed_m_s) const {
  const std::size_t bins = speed_bins();
  if (!(speed_m_s >= edges_.front() && speed_m_s <= edges_.back())) return bins;
  const auto upper = std::upper_bound(edges_.begin(), edges_.end(), speed_m_s);
  return std::min(bins - 1, static_cast<std::size_t>(upper - edges_.begin()) - 1);
}

bool SpeedBinnedComparison::add(double speed_m_s, std::span<const double> measured,
                                std::span<const double> simulated) {
  const std::size_t n = frequencies_.size();
  if (measured.size() != n || simulated.size() != n)
    throw std::invalid_argument(
        "speed-binned comparison: a row has " + std::to_string(measured.size()) + " and " +
        std::to_string(simulated.size()) + " values, expected " + std::to_string(n));
  const std::size_t b = bin_of(speed_m_s);
  if (b == speed_bins()) {
    ++outside_;
    return false;
  }
  ++counts_[b];
  speed_sums_[b] += speed_m_s;
  double* m = measured_sums_.data() + b * n;
  double* s = simulated_sums_.data() + b * n;
  for (std::size_t k = 0; k < n; ++k) {
    m[k] += measured[k];
    s[k] += simulated[k];
  }
  return true;
}

SpeedBinResult SpeedBinnedComparison::result(std::size_t bin) const {
  if (bin >= speed_bins())
    throw std::invalid_argument("speed-binned comparison: no bin " + std::to_string(bin));
  const std::size_t n = frequencies_.size();
  SpeedBinResult r;
  r.min_speed_m_s = edges_[bin];
  r.max_speed_m_s = edges_[bin + 1];
  r.rows = counts_[bin];
  r.measured_mean.assign(n, 0.0);
  r.simulated_mean.assign(n, 0.0);
  if (r.rows == 0) {
    r.mean_speed_m_s = r.lsd_db = r.measured_weighted_mean = r.simulated_weighted_mean =
        r.weighted_mean_log10_difference = kNaN;
    return r;
  }
  const double count = static_cast<double>(r.rows);
  r.mean_speed_m_s = speed_sums_[bin] / count;
  for (std::size_t k = 0; k < n; ++k) {
    r.measured_mean[k] = measured_sums_[bin * n + k] / count;
    r.simulated_mean[k] = simulated_sums_[bin * n + k] / count;
  }
  const std::span<const double> measured_band =
      std::span<const double>(r.measured_mean).subspan(band_first_, band_last_ - band_first_);
  const std::span<const double> simulated_band =
      std::span<const double>(r.simulated_mean).subspan(band_first_, band_last_ - band_first_);
  r.lsd_db = log_spectral_distance_db(measured_band, simulated_band);
  const std::vector<double> band_frequencies(
      frequencies_.begin() + static_cast<std::ptrdiff_t>(band_first_),
      frequencies_.begin() + static_cast<std::ptrdiff_t>(band_last_));
  r.measured_weighted_mean =
      weighted_mean_of(band_frequencies, measured_band, r.mean_speed_m_s, threshold_);
  r.simulated_weighted_mean =
      weighted_mean_of(band_frequencies, simulated_band, r.mean_speed_m_s, threshold_);
  r.weighted_mean_log10_difference =
      r.measured_weighted_mean > 0 && r.simulated_weighted_mean > 0
          ? std::log10(r.simulated_weighted_mean / r.measured_weighted_mean)
          : kNaN;
  return r;
}

std::vector<SpeedBinResult> SpeedBinnedComparison::results() const {
  std::vector<SpeedBinResult> all;
  all.reserve(speed_bins());
  for (std::size_t b = 0; b < speed_bins(); ++b) all.push_back(result(b));
  return all;
}

ComparisonSummary SpeedBinnedComparison::summarize(std::span<const SpeedBinResult> results,
                                                   std::uint64_t rows_outside_speed_range) {
  ComparisonSummary s;
  s.rows_outside_speed_range = rows_outside_speed_range;
  double lsd = 0.0, descriptor = 0.0;
  std::size_t lsd_count = 0, descriptor_count = 0;
  for (const auto& r : results) {
    s.rows += r.rows;
    if (r.rows == 0) continue;
    ++s.bins_with_rows;
    if (std::isfinite(r.lsd_db)) lsd += r.lsd_db, ++lsd_count;
    if (std::isfinite(r.weighted_mean_log10_difference))
      descriptor += r.weighted_mean_log10_difference, ++descriptor_count;
  }
  s.mean_lsd_db = lsd_count > 0 ? lsd / static_cast<double>(lsd_count) : kNaN;
  s.mean_weighted_mean_log10_difference =
      descriptor_count > 0 ? descriptor / static_cast<double>(descriptor_count) : kNaN;
  return s;
}

void SpeedBinnedComparison::reset() {
  std::fill(counts_.begin(), counts_.end(), 0);
  std::fill(speed_sums_.begin(), speed_sums_.end(), 0.0);
  std::fill(measured_sums_.begin(), measured_sums_.end(), 0.0);
  std::fill(simulated_sums_.begin(), simulated_sums_.end(), 0.0);
  outside_ = 0;
}

}  // namespace nibrig::model::measure
