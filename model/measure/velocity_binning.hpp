// Turns a vibration recording into the paper's velocity-dependent spectrum (io::VelocitySpectrum):
// one magnitude spectrum per tip speed, either from the constant-speed blocks of a turntable
// recording or from a recording with a continuous speed signal (live rig, drawing trajectories).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "model/io/velocity_spectrum.hpp"
#include "model/measure/spectrogram.hpp"
#include "model/measure/step_segmentation.hpp"

namespace nibrig::model::measure {

// Frequencies kept: min_frequency_hz <= f < max_frequency_hz (half-open, so that the defaults on
// the paper's 1500-sample windows at 1 kHz keep exactly its 741 bins, 6.00-499.33 Hz). The kept
// spectrum is smoothed by a centred moving average over smoothing_bins bins (odd; 1 = none) whose
// span shrinks symmetrically at the ends (first and last bins unchanged), like MATLAB's smooth(y,
// 5) in the paper's code. `window` applies to spectrum_per_step (the paper used a plain FFT:
// rectangular).
struct BinningSettings {
  double min_frequency_hz = 6.0;
  double max_frequency_hz = 500.0;
  std::size_t smoothing_bins = 5;
  Window window = Window::rectangular;
};

// Peak amplitude spectrum of every step's window (mean removed, SpectrumAnalyzer::amplitude
// scaling, i.e. |FFT|·2/N for the rectangular window as in the paper), averaged over the sweeps
// that hold the same speed, cropped and smoothed. Speeds come out in the order they first appear in
// the steps. All steps must have windows of one length inside the signal (std::invalid_argument
// otherwise).
io::VelocitySpectrum spectrum_per_step(std::span<const double> acceleration, double sample_rate_hz,
                                       const StepSegmentation& steps,
                                       const BinningSettings& settings);

// What spectrum_by_speed could not use, so that callers can report it.
struct SpeedBinningReport {
  std::vector<std::size_t> segments_per_bin;  // one per speed bin (before dropping empty ones)
  std::vector<std::size_t> empty_bins;        // indices of speed bins without any segment (dropped)
  std::size_t segments_outside_speed_record =
      0;                                  // segment centre outside the speed signal's time span
  std::size_t segments_outside_bins = 0;  // speed below the first or above the last edge
};

// Spectrogram of the acceleration (SpectrogramSettings: window, overlap, scaling as documented
// there); the speed at each segment centre is interpolated linearly in the speed signal (sample i
// at time i / speed_rate_hz); segment amplitudes are averaged per speed bin [edge_b, edge_b+1) (the
// last bin closed), and each bin's speed is the mean of the speeds actually in it. Bins without
// segments are dropped, with a spdlog warning and in `report`. Frequencies are cropped and smoothed
// as in BinningSettings (its `window` is not used: the spectrogram's is). Throws
// std::invalid_argument on bad rates, fewer than 2 or non-increasing edges, and std::runtime_error
// when no bin gets a segment.
io::VelocitySpectrum spectrum_by_speed(std::span<const double> acceleration,
                                       double acceleration_rate_hz,
                                       std::span<const double> speed_m_s, double speed_rate_hz,
                                       std::span<const double> speed_bin_edges_m_s,
                                       const SpectrogramSettings& spectrogram,
                                       const BinningSettings& settings,
                                       SpeedBinningReport* report = nullptr);

// The smoothing used above, exposed for tests and for spectra made elsewhere.
std::vector<double> smooth_shrinking_span(std::span<const double> values, std::size_t span);

}  // namespace nibrig::model::measure
