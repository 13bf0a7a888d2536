// One-sided spectra of fixed-length real segments through a single FFTW r2c plan made once and
// reused: the building block of spectrograms, step spectra and envelopes in model/measure. Scaling
// conventions (peak amplitude, one-sided PSD) are stated with each function below.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace nibrig::model::measure {

enum class Window { rectangular, hann };

// The window's N coefficients. Hann is the periodic ("DFT-even") form w[n] = 0.5 - 0.5 cos(2πn/N),
// the one scipy.signal.get_window('hann', N) returns, so that spectrograms compare bin for bin with
// scipy.
std::vector<double> window_coefficients(Window window, std::size_t length);

// Not copyable (it owns FFTW memory and a plan); movable. The scratch buffers make amplitude() and
// power_spectral_density() non-const: use one analyzer per thread. The plan is made with
// FFTW_ESTIMATE: planning costs microseconds and gives the same plan on every run. FFTW_MEASURE
// would time candidate algorithms (milliseconds or more per size, choice varying from run to run)
// to make the transforms somewhat faster — but the transforms are a small part of a spectrogram's
// time (tests/bench/README.md).
class SpectrumAnalyzer {
 public:
  // segment_length >= 2, else std::invalid_argument.
  SpectrumAnalyzer(std::size_t segment_length, Window window);
  ~SpectrumAnalyzer();
  SpectrumAnalyzer(SpectrumAnalyzer&&) noexcept;
  SpectrumAnalyzer& operator=(SpectrumAnalyzer&&) noexcept;
  SpectrumAnalyzer(const SpectrumAnalyzer&) = delete;
  SpectrumAnalyzer& operator=(const SpectrumAnalyzer&) = delete;

  std::size_t segment_length() const;
  Window window() const;
  // Number of one-sided bins, N/2 + 1.
  std::size_t bins() const;
  // k * fs / N.
  double bin_frequency_hz(std::size_t k, double sample_rate_hz) const;

  // Single-sided peak amplitude: out[k] = c_k |X_k| / Σw with c_k = 2, except c_0 = 1 and, for even
  // N, c_{N/2} = 1. A sinusoid A·sin(2πft) with f on bin k reads A at k (coherent gain divided
  // out); a constant c reads c at k = 0 when remove_mean is false. Off-bin sinusoids read lower
  // (scalloping): at most 3.92 dB (factor 2/π) with the rectangular window and 1.42 dB (factor
  // 0.849) with Hann. remove_mean subtracts the segment's plain mean before windowing, as the
  // paper's code does. segment.size() must equal segment_length() and out.size() bins(), else
  // std::invalid_argument.
  void amplitude(std::span<const double> segment, std::span<double> out, bool remove_mean = true);

  // One-sided power spectral density in units²/Hz: out[k] = c_k |X_k|² / (fs Σw²) with c_k = 2
  // except at k = 0 and the even-N Nyquist bin (c = 1). Then Σ_k out[k]·Δf, Δf = fs/N, equals Σ(x
  // w)²/Σw²: exactly the mean square of the (mean-removed) segment for the rectangular window
  // (Parseval), and its window-weighted mean square for Hann, which equals the mean square in
  // expectation for a stationary signal (the usual "energy correction").
  void power_spectral_density(std::span<const double> segment, double sample_rate_hz,
                              std::span<double> out, bool remove_mean = true);

 private:
  struct Impl;
  // Loads the (optionally mean-removed) windowed segment and runs the transform into the output
  // buffer.
  void transform(std::span<const double> segment, std::size_t out_size, bool remove_mean);
  std::unique_ptr<Impl> impl_;
};

}  // namespace nibrig::model::measure
