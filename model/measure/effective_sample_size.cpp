#include "model/measure/effective_sample_size.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "model/numeric/real_fft.hpp"

namespace nibrig::model::measure {

namespace {

// Autocovariance at lags 0..n-1 (divisor n) by zero-padded FFT: O(n log n) instead of O(n²).
std::vector<double> autocovariance(std::span<const double> x, double mean) {
  const std::size_t n = x.size();
  std::size_t padded = 1;
  while (padded < 2 * n) padded *= 2;
  numeric::RealFft fft(padded, numeric::RealFft::Plans::forward_and_backward);
  const std::span<double> real = fft.real();
  for (std::size_t i = 0; i < padded; ++i) real[i] = i < n ? x[i] - mean : 0.0;
  fft.forward();
  for (std::complex<double>& c : fft.spectrum()) {
    const double re = c.real();
    const double im = c.imag();
    c = {re * re + im * im, 0.0};
  }
  fft.backward();
  std::vector<double> acov(n);
  // FFTW's c2r is unnormalised (factor `padded`); the autocovariance divides by n.
  for (std::size_t k = 0; k < n; ++k) {
    acov[k] = real[k] / (static_cast<double>(padded) * static_cast<double>(n));
  }
  return acov;
}

}  // namespace

AutocorrelationSummary summarize_autocorrelation(std::span<const double> x) {
  if (x.size() < 2) throw std::invalid_argument("autocorrelation: need at least 2 samples");
  for (double v : x) {
    if (!std::isfinite(v)) throw std::invalid_argument("autocorrelation: non-finite sample");
  }
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  const std::vector<double> acov = autocovariance(x, mean);
  AutocorrelationSummary s;
  s.variance = acov[0];
  if (!(acov[0] > 0.0)) {
    // A constant series: every sample is the same, the mean is exact.
    s.effective_samples = static_cast<double>(x.size());
    return s;
  }
  double tau = 1.0;
  std::size_t m = 1;
  for (; m < x.size(); ++m) {
    tau += 2.0 * acov[m] / acov[0];
    if (static_cast<double>(m) >= 5.0 * tau) break;
  }
  s.window = m;
  s.integrated_time_samples = std::max(1.0, tau);
  s.effective_samples = static_cast<double>(x.size()) / s.integrated_time_samples;
  return s;
}

double standard_error_of_mean(const AutocorrelationSummary& summary, std::size_t n) {
  return std::sqrt(summary.variance * summary.integrated_time_samples / static_cast<double>(n));
}

}  // namespace nibrig::model::measure
