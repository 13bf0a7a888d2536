// Measured against simulated vibration, speed by speed: rows of two spectrograms taken at the same
// instants (a rig's measured acceleration and the simulation driven by the measured speed) are
// averaged per speed bin, and each bin's pair of mean spectra is compared the way the tree compares
// spectra elsewhere — dB RMS of their ratio (forcing/leave_one_out's log_spectrum_error) and the
// log10 ratio of the perceptually weighted mean (forcing/descriptor_error), on the catalog's band.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "model/measure/threshold_curve.hpp"

namespace nibrig::model::measure {

// speed_bins bins with geometrically spaced edges from min_speed_m_s to max_speed_m_s (the paper's
// steps over 17-250 mm/s are roughly geometric, and so is what a finger tells apart), the last bin
// closed. Distances use the frequencies min_frequency_hz <= f < max_frequency_hz: the catalog's
// band (BinningSettings' defaults), so that a distance here reads like the catalog's repeatability.
struct SpeedBinnedComparisonSettings {
  double min_speed_m_s = 0.017;
  double max_speed_m_s = 0.250;
  std::size_t speed_bins = 12;
  double min_frequency_hz = 6.0;
  double max_frequency_hz = 500.0;
};

// The geometric edges described above: speed_bins + 1 values, first and last exactly min and max.
std::vector<double> geometric_speed_edges(double min_speed_m_s, double max_speed_m_s,
                                          std::size_t speed_bins);

struct SpeedBinResult {
  double min_speed_m_s = 0.0, max_speed_m_s = 0.0;
  double mean_speed_m_s = 0.0;  // of the rows in the bin; NaN when empty
  std::size_t rows = 0;
  // Mean peak amplitude of the rows at every frequency of the spectrograms (not only the band).
  std::vector<double> measured_mean, simulated_mean;
  // RMS over the band's bins where both means are positive of 20·log10(simulated / measured), dB;
  // NaN when the bin is empty or no band bin is positive in both.
  double lsd_db = 0.0;
  // compute_vibration_descriptors' weighted_mean of each mean spectrum on the band, and
  // log10(simulated / measured) of the two (the space's descriptor is the log10 of the weighted
  // mean, so this is the descriptor's difference); NaN when empty or either is not positive.
  double measured_weighted_mean = 0.0, simulated_weighted_mean = 0.0;
  double weighted_mean_log10_difference = 0.0;
};

// Over the bins that have rows: the plain mean of their lsd_db and of their descriptor differences
// (each bin counts once, however long the turntable stayed there), NaN when none has.
struct ComparisonSummary {
  std::size_t bins_with_rows = 0;
  std::uint64_t rows = 0, rows_outside_speed_range = 0;
  double mean_lsd_db = 0.0;
  double mean_weighted_mean_log10_difference = 0.0;
};

class SpeedBinnedComparison {
 public:
  // frequencies_hz: the spectrograms' frequencies (both streams share them). Throws
  // std::invalid_argument for no speed bin, speeds that are not 0 < min < max and finite, fewer
  // than two frequencies, or a band holding fewer than two of them (the descriptor needs two).
  SpeedBinnedComparison(std::vector<double> frequencies_hz,
                        const SpeedBinnedComparisonSettings& settings, ThresholdCurve threshold);

  const std::vector<double>& frequencies_hz() const { return frequencies_; }
  const std::vector<double>& speed_edges_m_s() const { return edges_; }
  // The bin of a speed, or speed_bins() when it is outside the edges (or NaN).
  std::size_t bin_of(double speed_m_s) const;
  std::size_t speed_bins() const { return edges_.size() - 1; }
  // Indices [first, last) of the band's frequencies.
  std::size_t band_first() const { return band_first_; }
  std::size_t band_last() const { return band_last_; }

  // One pair of rows taken over the same span while the surface moved at speed_m_s (the mean
  // measured speed over that span). False, and only counted, when the speed is outside the bins.
  // No allocation. Rows must have frequencies_hz().size() values (std::invalid_argument otherwise).
  bool add(double speed_m_s, std::span<const double> measured, std::span<const double> simulated);

  // Allocates: for the analysis thread's snapshots and the report, not for every row.
  SpeedBinResult result(std::size_t bin) const;
  std::vector<SpeedBinResult> results() const;
  static ComparisonSummary summarize(std::span<const SpeedBinResult> results,
                                     std::uint64_t rows_outside_speed_range);
  ComparisonSummary summary() const { return summarize(results(), outside_); }
  std::uint64_t rows_outside_speed_range() const { return outside_; }

  void reset();

 private:
  std::vector<double> frequencies_;
  std::vector<double> edges_;
  std::size_t band_first_ = 0, band_last_ = 0;
  ThresholdCurve threshold_;
  // Per bin: row count, summed speed, summed spectra (bins × frequencies, row-major).
  std::vector<std::uint64_t> counts_;
  std::vector<double> speed_sums_;
  std::vector<double> measured_sums_, simulated_sums_;
  std::uint64_t outside_ = 0;
};

// The speed samples (sample i taken at i / speed_rate_hz, as spectrum_by_speed reads a speed
// signal) inside a spectrogram row's span [first_sample, first_sample + length) / rate_hz: indices
// [begin, end). A span shorter than the speed's period that holds no sample gets the one sample at
// or after its start, so every row has a speed.
struct SampleRange {
  std::uint64_t begin = 0, end = 0;
};
SampleRange speed_samples_of_span(std::uint64_t first_sample, std::size_t length, double rate_hz,
                                  double speed_rate_hz);

// RMS of 20·log10(simulated / measured) over the bins where both amplitudes are positive
// (log_spectrum_error's definition), dB; NaN when no bin is usable or the sizes differ.
double log_spectral_distance_db(std::span<const double> measured,
                                std::span<const double> simulated);

}  // namespace nibrig::model::measure
