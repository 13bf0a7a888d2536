#include "model/measure/descriptors.hpp"

#include <algorithm>
#include <stdexcept>

namespace nibrig::model::measure {

VibrationDescriptors compute_vibration_descriptors(const io::VelocitySpectrum& spectrum,
                                                   const ThresholdCurve& threshold, int max_bands) {
  const std::vector<double>& f = spectrum.frequencies_hz;
  if (f.size() < 2)
    throw std::invalid_argument("vibration descriptors: need at least 2 frequencies");
  for (std::size_t i = 1; i < f.size(); ++i) {
    if (!(f[i] > f[i - 1])) {
      throw std::invalid_argument("vibration descriptors: frequencies must increase strictly");
    }
  }
  if (spectrum.amplitude_m_s2.empty()) {
    throw std::invalid_argument("vibration descriptors: the spectrum has no speed row");
  }
  if (max_bands < 1) throw std::invalid_argument("vibration descriptors: max_bands must be >= 1");
  const auto ratio = weight_by_threshold(spectrum, threshold);  // checks row lengths

  const std::size_t n = f.size();
  std::vector<double> edge(n + 1);  // cell i is [edge[i], edge[i+1])
  edge[0] = f[0] - 0.5 * (f[1] - f[0]);
  for (std::size_t i = 1; i < n; ++i) edge[i] = 0.5 * (f[i - 1] + f[i]);
  edge[n] = f[n - 1] + 0.5 * (f[n - 1] - f[n - 2]);

  // Per-bin weighted power density averaged over speeds: mean_s r².
  const double speeds = static_cast<double>(ratio.size());
  std::vector<double> density(n, 0.0);
  double sum_ratio = 0.0;
  for (const auto& row : ratio) {
    for (std::size_t i = 0; i < n; ++i) {
      density[i] += row[i] * row[i] / speeds;
      sum_ratio += row[i];
    }
  }

  VibrationDescriptors d;
  d.weighted_mean = sum_ratio / (speeds * static_cast<double>(n));
  for (std::size_t i = 0; i < n; ++i) d.weighted_power += density[i] * (edge[i + 1] - edge[i]);

  const double lo = edge[0];
  const double span = edge[n] - edge[0];
  for (int k = 1; k <= max_bands; ++k) {
    std::vector<double> bands(static_cast<std::size_t>(k), 0.0);
    for (int j = 0; j < k; ++j) {
      const double a = lo + span * j / k;
      const double b = j + 1 == k ? edge[n] : lo + span * (j + 1) / k;
      for (std::size_t i = 0; i < n; ++i) {
        const double overlap = std::min(b, edge[i + 1]) - std::max(a, edge[i]);
        if (overlap > 0.0) bands[static_cast<std::size_t>(j)] += density[i] * overlap;
      }
    }
    d.band_energies[k] = std::move(bands);
  }
  return d;
}

std::size_t weigh_catalog_vibration(io::Catalog& catalog, const ThresholdCurve& threshold,
                                    int max_bands) {
  std::size_t weighted = 0;
  for (auto& p : catalog.pairings) {
    if (!p.vibration) continue;
    VibrationDescriptors d;
    try {
      d = compute_vibration_descriptors(p.vibration->spectrum, threshold, max_bands);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("pairing " + p.tool + "/" + p.surface + ": " + e.what());
    }
    p.vibration->weighted_mean = d.weighted_mean;
    p.vibration->weighted_power = d.weighted_power;
    p.vibration->band_energies = d.band_energies;
    p.vibration->threshold_curve = threshold.source();
    ++weighted;
  }
  return weighted;
}

}  // namespace nibrig::model::measure
