#include "tests/rt/spectrum_check.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "model/measure/spectrum_analyzer.hpp"
#include "model/measure/velocity_binning.hpp"
#include "model/numeric/amplitude_convention.hpp"

namespace nibrig::rt::testing {

std::vector<double> catalog_analysis(const std::vector<double>& x, double fs,
                                     const std::vector<double>& frequencies) {
  const auto n = static_cast<std::size_t>(model::numeric::kCatalogWindowSeconds * fs);
  model::measure::SpectrumAnalyzer analyzer(n, model::measure::Window::rectangular);
  std::vector<double> mean(analyzer.bins(), 0.0), a(analyzer.bins());
  const std::size_t windows = x.size() / n;
  for (std::size_t w = 0; w < windows; ++w) {
    analyzer.amplitude(std::span(x).subspan(w * n, n), a);
    for (std::size_t k = 0; k < a.size(); ++k) mean[k] += a[k] / static_cast<double>(windows);
  }
  mean = model::measure::smooth_shrinking_span(mean, 5);
  std::vector<double> out;
  for (double f : frequencies) {
    const double bin = f * static_cast<double>(n) / fs;
    const auto k = static_cast<std::size_t>(bin);
    const double u = bin - static_cast<double>(k);
    out.push_back((1 - u) * mean[k] + u * mean[k + 1]);
  }
  return out;
}

SpectrumAgreement compare_spectra(const std::vector<double>& got, const std::vector<double>& want) {
  std::vector<double> err;
  double sum_got = 0, sum_want = 0;
  for (std::size_t i = 0; i < want.size(); ++i) {
    err.push_back(std::abs(20 * std::log10(got[i] / want[i])));
    sum_got += got[i] * got[i];
    sum_want += want[i] * want[i];
  }
  std::sort(err.begin(), err.end());
  return {err[err.size() / 2], err[err.size() * 95 / 100], 10 * std::log10(sum_got / sum_want)};
}

}  // namespace nibrig::rt::testing
