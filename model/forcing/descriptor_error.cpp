#include "model/forcing/descriptor_error.hpp"

#include <cmath>
#include <stdexcept>

#include "model/measure/descriptors.hpp"

namespace nibrig::model::forcing {

double percent_off(double log10_ratio) { return 100.0 * (std::pow(10.0, log10_ratio) - 1.0); }

DescriptorError descriptor_error(const std::string& tool, const std::string& surface,
                                 const io::VelocitySpectrum& predicted,
                                 const io::VelocitySpectrum& measured,
                                 const measure::ThresholdCurve& threshold) {
  const auto p = measure::compute_vibration_descriptors(predicted, threshold, kMaxDescriptorBands);
  const auto m = measure::compute_vibration_descriptors(measured, threshold, kMaxDescriptorBands);
  auto ratio = [&](double predicted_value, double measured_value, const std::string& what) {
    if (!(predicted_value > 0 && measured_value > 0))
      throw std::invalid_argument("descriptor error of " + tool + " on " + surface + ": the " +
                                  what + " is not positive (predicted " +
                                  std::to_string(predicted_value) + ", measured " +
                                  std::to_string(measured_value) + "), so it has no logarithm");
    return std::log10(predicted_value / measured_value);
  };
  DescriptorError error{
      tool, surface, ratio(p.weighted_mean, m.weighted_mean, "weighted mean"), {}};
  for (int k = kMinDescriptorBands; k <= kMaxDescriptorBands; ++k) {
    auto& bands = error.log10_band_energies[k];
    for (std::size_t j = 0; j < static_cast<std::size_t>(k); ++j)
      bands.push_back(
          ratio(p.band_energies.at(k)[j], m.band_energies.at(k)[j],
                "energy of band " + std::to_string(j + 1) + " of " + std::to_string(k)));
  }
  return error;
}

DescriptorErrorSummary summarize(const std::vector<DescriptorError>& errors) {
  DescriptorErrorSummary summary;
  summary.errors = errors.size();
  if (errors.empty()) return summary;
  double squares = 0.0, band_squares = 0.0;
  std::size_t band_count = 0;
  summary.worst = &errors.front();
  for (const auto& e : errors) {
    squares += e.log10_weighted_mean * e.log10_weighted_mean;
    if (std::abs(e.log10_weighted_mean) > std::abs(summary.worst->log10_weighted_mean)) summary.worst = &e;
    for (double b : e.log10_band_energies.at(kMaxDescriptorBands)) {
      band_squares += b * b;
      ++band_count;
    }
  }
  summary.rms_log10_weighted_mean = std::sqrt(squares / static_cast<double>(errors.size()));
  summary.rms_log10_band_energy = std::sqrt(band_squares / static_cast<double>(band_count));
  return summary;
}

}  // namespace nibrig::model::forcing
