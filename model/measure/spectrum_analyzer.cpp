#include "model/measure/spectrum_analyzer.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>

#include "model/numeric/real_fft.hpp"

namespace nibrig::model::measure {

std::vector<double> window_coefficients(Window window, std::size_t length) {
  std::vector<double> w(length, 1.0);
  if (window == Window::hann) {
    for (std::size_t n = 0; n < length; ++n) {
      w[n] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(n) /
                                  static_cast<double>(length));
    }
  }
  return w;
}

namespace {

std::size_t checked_length(std::size_t segment_length) {
  if (segment_length < 2) {
    throw std::invalid_argument("SpectrumAnalyzer: segment length must be at least 2, got " +
                                std::to_string(segment_length));
  }
  return segment_length;
}

void require_size(std::size_t got, std::size_t expected, const char* what) {
  if (got != expected) {
    throw std::invalid_argument(std::string("SpectrumAnalyzer: ") + what + " has " +
                                std::to_string(got) + " values, expected " +
                                std::to_string(expected));
  }
}

}  // namespace

struct SpectrumAnalyzer::Impl {
  Impl(std::size_t segment_length, Window w)
      : length(segment_length),
        window(w),
        coefficients(window_coefficients(w, segment_length)),
        sum_w(std::accumulate(coefficients.begin(), coefficients.end(), 0.0)),
        sum_w2(std::inner_product(coefficients.begin(), coefficients.end(), coefficients.begin(),
                                  0.0)),
        fft(segment_length, numeric::RealFft::Plans::forward) {}

  std::size_t length;
  Window window;
  std::vector<double> coefficients;
  double sum_w;
  double sum_w2;
  numeric::RealFft fft;
};

SpectrumAnalyzer::SpectrumAnalyzer(std::size_t segment_length, Window window)
    : impl_(std::make_unique<Impl>(checked_length(segment_length), window)) {}

SpectrumAnalyzer::~SpectrumAnalyzer() = default;
SpectrumAnalyzer::SpectrumAnalyzer(SpectrumAnalyzer&&) noexcept = default;
SpectrumAnalyzer& SpectrumAnalyzer::operator=(SpectrumAnalyzer&&) noexcept = default;

std::size_t SpectrumAnalyzer::segment_length() const { return impl_->length; }
Window SpectrumAnalyzer::window() const { return impl_->window; }
std::size_t SpectrumAnalyzer::bins() const { return impl_->length / 2 + 1; }

double SpectrumAnalyzer::bin_frequency_hz(std::size_t k, double sample_rate_hz) const {
  return static_cast<double>(k) * sample_rate_hz / static_cast<double>(impl_->length);
}

void SpectrumAnalyzer::transform(std::span<const double> segment, std::size_t out_size,
                                 bool remove_mean) {
  Impl& s = *impl_;
  require_size(segment.size(), s.length, "segment");
  require_size(out_size, bins(), "output");
  double mean = 0.0;
  if (remove_mean) {
    // Four running sums: one chain of dependent additions would bound this loop by the adder's
    // latency, a third of a spectrogram's time at 1024-sample segments.
    double acc[4] = {0.0, 0.0, 0.0, 0.0};
    std::size_t n = 0;
    for (; n + 4 <= s.length; n += 4) {
      for (std::size_t j = 0; j < 4; ++j) acc[j] += segment[n + j];
    }
    for (; n < s.length; ++n) acc[0] += segment[n];
    mean = ((acc[0] + acc[1]) + (acc[2] + acc[3])) / static_cast<double>(s.length);
  }
  double* in = s.fft.real().data();
  const double* w = s.coefficients.data();
  for (std::size_t n = 0; n < s.length; ++n) in[n] = (segment[n] - mean) * w[n];
  s.fft.forward();
}

void SpectrumAnalyzer::amplitude(std::span<const double> segment, std::span<double> out,
                                 bool remove_mean) {
  transform(segment, out.size(), remove_mean);
  const Impl& s = *impl_;
  const std::complex<double>* X = s.fft.spectrum().data();
  const double scale = 2.0 / s.sum_w;
  const std::size_t nb = out.size();
  // sqrt(re² + im²), not std::hypot: hypot's overflow guard costs ~4x here, and spectra of physical
  // signals are nowhere near 1e154.
  for (std::size_t k = 0; k < nb; ++k) {
    out[k] = scale * std::sqrt(X[k].real() * X[k].real() + X[k].imag() * X[k].imag());
  }
  // DC and (even-N) Nyquist have no mirror image in the two-sided spectrum: not doubled.
  out[0] *= 0.5;
  if (s.length % 2 == 0) out[nb - 1] *= 0.5;
}

void SpectrumAnalyzer::power_spectral_density(std::span<const double> segment,
                                              double sample_rate_hz, std::span<double> out,
                                              bool remove_mean) {
  if (!(sample_rate_hz > 0.0) || !std::isfinite(sample_rate_hz)) {
    throw std::invalid_argument("SpectrumAnalyzer: sample rate must be positive and finite");
  }
  transform(segment, out.size(), remove_mean);
  const Impl& s = *impl_;
  const std::complex<double>* X = s.fft.spectrum().data();
  const double scale = 2.0 / (sample_rate_hz * s.sum_w2);
  const std::size_t nb = out.size();
  for (std::size_t k = 0; k < nb; ++k)
    out[k] = scale * (X[k].real() * X[k].real() + X[k].imag() * X[k].imag());
  out[0] *= 0.5;
  if (s.length % 2 == 0) out[nb - 1] *= 0.5;
}

}  // namespace nibrig::model::measure
