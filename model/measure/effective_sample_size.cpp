#include "model/measure/effective_sample_size.hpp"

#include <fftw3.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "model/measure/fftw_planner_lock.hpp"

namespace nibrig::model::measure {

namespace {

// Autocovariance at lags 0..n-1 (divisor n) by zero-padded FFT: O(n log n) instead of O(n²).
std::vector<double> autocovariance(std::span<const double> x, double mean) {
  const std::size_t n = x.size();
  std::size_t padded = 1;
  while (padded < 2 * n) padded *= 2;
  const std::size_t bins = padded / 2 + 1;
  std::unique_ptr<double, decltype(&fftw_free)> real(
      static_cast<double*>(fftw_malloc(sizeof(double) * padded)), &fftw_free);
  std::unique_ptr<fftw_complex, decltype(&fftw_free)> spec(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * bins)), &fftw_free);
  if (!real || !spec) throw std::bad_alloc();
  fftw_plan forward = nullptr;
  fftw_plan backward = nullptr;
  {
    std::lock_guard lock(detail::fftw_planner_mutex());
    forward = fftw_plan_dft_r2c_1d(static_cast<int>(padded), real.get(), spec.get(), FFTW_ESTIMATE);
    backward =
        fftw_plan_dft_c2r_1d(static_cast<int>(padded), spec.get(), real.get(), FFTW_ESTIMATE);
  }
  for (std::size_t i = 0; i < padded; ++i) real.get()[i] = i < n ? x[i] - mean : 0.0;
  fftw_execute(forward);
  for (std::size_t k = 0; k < bins; ++k) {
    auto& c = spec.get()[k];
    c[0] = c[0] * c[0] + c[1] * c[1];
    c[1] = 0.0;
  }
  fftw_execute(backward);
  {
    std::lock_guard lock(detail::fftw_planner_mutex());
    fftw_destroy_plan(forward);
    fftw_destroy_plan(backward);
  }
  std::vector<double> acov(n);
  // FFTW's c2r is unnormalised (factor `padded`); the autocovariance divides by n.
  for (std::size_t k = 0; k < n; ++k) {
    acov[k] = real.get()[k] / (static_cast<double>(padded) * static_cast<double>(n));
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
