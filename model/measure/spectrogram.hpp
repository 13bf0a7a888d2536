// Short-time magnitude spectra of an acceleration (or any) signal: the velocity-dependent
// spectrogram of the paper is built from these, binned by speed (velocity_binning.hpp).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <vector>

#include "model/measure/spectrum_analyzer.hpp"

namespace nibrig::model::measure {

// Segments of segment_length samples start every hop samples (overlap = segment_length - hop; the
// defaults give 75 %). Each segment has its plain mean removed (when remove_mean), is multiplied by
// the window (periodic Hann by default) and transformed; a trailing part shorter than one segment
// is not analysed (no zero padding).
struct SpectrogramSettings {
  std::size_t segment_length = 1024;
  std::size_t hop = 256;
  Window window = Window::hann;
  bool remove_mean = true;
};

// amplitude(i, k) is the single-sided PEAK amplitude (signal units, m/s² for acceleration) of
// segment i at frequencies_hz[k] = k fs / segment_length, coherent-gain corrected as
// SpectrumAnalyzer::amplitude: a sinusoid of amplitude A on a bin centre reads A. times_s[i] is the
// segment's centre, (first sample + segment_length / 2) / fs — scipy.signal.spectrogram's
// convention.
struct Spectrogram {
  std::vector<double> frequencies_hz;
  std::vector<double> times_s;
  Eigen::MatrixXd amplitude;  // rows = times, cols = frequencies
};

// Throws std::invalid_argument when segment_length < 2, hop == 0, the rate is not positive and
// finite, or the signal is shorter than one segment.
Spectrogram compute_spectrogram(std::span<const double> signal, double sample_rate_hz,
                                const SpectrogramSettings& settings);

}  // namespace nibrig::model::measure
