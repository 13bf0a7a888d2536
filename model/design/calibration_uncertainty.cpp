#include "model/design/calibration_uncertainty.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

#include "model/forcing/hermite_curve.hpp"
#include "model/measure/descriptors.hpp"
#include "model/space/catalog_descriptors.hpp"

namespace nibrig::model::design {

namespace {

// log10 of the vibration descriptors `names` asks for, in its order; friction (μ) left at 0.
Eigen::VectorXd calibration_log_descriptors(const io::VelocitySpectrum& spectrum,
                                            const measure::ThresholdCurve& threshold,
                                            const std::vector<std::string>& names) {
  const auto d = measure::compute_vibration_descriptors(spectrum, threshold);
  const std::string mu = space::paper_descriptor_names(1).front();
  const std::string weighted_mean = space::paper_descriptor_names(2).back();
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(names.size()));
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == mu) continue;
    if (names[i] == weighted_mean) {
      out(static_cast<Eigen::Index>(i)) = std::log10(d.weighted_mean);
      continue;
    }
    bool found = false;
    for (int bands = 2; bands <= 5 && !found; ++bands) {
      const auto band_names = space::paper_descriptor_names(static_cast<std::size_t>(bands) + 1);
      for (std::size_t j = 1; j < band_names.size(); ++j)
        if (band_names[j] == names[i]) {
          out(static_cast<Eigen::Index>(i)) = std::log10(d.band_energies.at(bands).at(j - 1));
          found = true;
          break;
        }
    }
    if (!found)
      throw std::invalid_argument("calibration uncertainty: no descriptor named '" + names[i] +
                                  "'");
  }
  return out;
}

// The descriptors' change per unit of a log perturbation `delta` [speed][frequency], by a central
// difference at a step small against the curvature of log10 of a sum of exponentials.
Eigen::VectorXd calibration_sensitivity(
    const io::VelocitySpectrum& spectrum, const measure::ThresholdCurve& threshold,
    const std::vector<std::string>& names,
    const std::function<double(std::size_t, std::size_t)>& delta) {
  constexpr double kStep = 1e-4;
  auto shifted = [&](double step) {
    io::VelocitySpectrum s = spectrum;
    for (std::size_t v = 0; v < s.amplitude_m_s2.size(); ++v)
      for (std::size_t j = 0; j < s.amplitude_m_s2[v].size(); ++j)
        s.amplitude_m_s2[v][j] *= std::exp(step * delta(v, j));
    return calibration_log_descriptors(s, threshold, names);
  };
  return (shifted(kStep) - shifted(-kStep)) / (2 * kStep);
}

}  // namespace

bool has_calibration_errors(const forcing::ForcingModel& model, const DesignPoint& point,
                            const std::string& surface) {
  if (model.surface_log_forcing_se.count(surface)) return true;
  for (const auto& share : point.mix)
    if (share.fraction > 0 && model.material_log_gain_se.count(share.material)) return true;
  return false;
}

Eigen::MatrixXd calibration_descriptor_covariance(const forcing::ForcingModel& model,
                                                  const DesignPoint& point,
                                                  const std::string& surface,
                                                  const io::VelocitySpectrum& spectrum,
                                                  const measure::ThresholdCurve& threshold,
                                                  const std::vector<std::string>& names) {
  const auto n = static_cast<Eigen::Index>(names.size());
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(n, n);
  calibration_log_descriptors(spectrum, threshold, names);  // names checked even with no errors
  for (const auto& share : point.mix) {
    const auto se = model.material_log_gain_se.find(share.material);
    if (se == model.material_log_gain_se.end() || share.fraction <= 0) continue;
    for (std::size_t k = 0; k < se->second.size(); ++k) {
      if (se->second[k] <= 0) continue;
      // ln M moves by the share times the knot's Hermite weight at each frequency.
      std::vector<double> weight(model.frequencies_hz.size(), 0.0);
      for (std::size_t j = 0; j < weight.size(); ++j)
        for (const auto& [knot, w] :
             forcing::hermite_weights(model.knot_frequencies_hz, model.frequencies_hz[j]))
          if (knot == k) weight[j] = w;
      const Eigen::VectorXd g = calibration_sensitivity(
          spectrum, threshold, names,
          [&](std::size_t, std::size_t j) { return share.fraction * weight[j]; });
      covariance += g * g.transpose() * se->second[k] * se->second[k];
    }
  }
  if (const auto se = model.surface_log_forcing_se.find(surface);
      se != model.surface_log_forcing_se.end()) {
    const Eigen::VectorXd g = calibration_sensitivity(
        spectrum, threshold, names,
        [&](std::size_t v, std::size_t j) { return se->second.at(v).at(j); });
    covariance += g * g.transpose();
  }
  return covariance;
}

}  // namespace nibrig::model::design
