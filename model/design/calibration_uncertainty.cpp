#include "model/design/calibration_uncertainty.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>

#include "model/forcing/hermite_curve.hpp"
#include "model/measure/descriptors.hpp"
#include "model/mechanics/ring_down.hpp"
#include "model/modal/frequency_response.hpp"
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

// Zero over `names`, once they are checked to be descriptors: a name that is not one is refused
// even when there is no error to add.
Eigen::MatrixXd zero_covariance(const io::VelocitySpectrum& spectrum, const measure::ThresholdCurve& threshold,
                                const std::vector<std::string>& names) {
  calibration_log_descriptors(spectrum, threshold, names);
  const auto n = static_cast<Eigen::Index>(names.size());
  return Eigen::MatrixXd::Zero(n, n);
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
  Eigen::MatrixXd covariance = zero_covariance(spectrum, threshold, names);
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

Eigen::MatrixXd material_constants_covariance(const modal::ModalModel& modal,
                                              const mechanics::RayleighDamping& damping,
                                              const mechanics::Material& material,
                                              const io::VelocitySpectrum& spectrum,
                                              const measure::ThresholdCurve& threshold,
                                              const std::vector<std::string>& names) {
  Eigen::MatrixXd covariance = zero_covariance(spectrum, threshold, names);
  // d ln|H(f_j)| / d ln(parameter), from the stylus at parameter × (1 ± h).
  constexpr double h = 1e-3;
  const auto log_response_slope = [&](const std::function<modal::ModalModel(double)>& at) {
    const auto up = modal::frequency_response(at(1 + h), spectrum.frequencies_hz);
    const auto down = modal::frequency_response(at(1 - h), spectrum.frequencies_hz);
    std::vector<double> slope(up.size());
    for (std::size_t j = 0; j < up.size(); ++j)
      slope[j] = (std::log(std::abs(up[j])) - std::log(std::abs(down[j]))) /
                 (std::log1p(h) - std::log1p(-h));
    return slope;
  };
  const auto sensitivity = [&](const std::vector<double>& slope) {
    return calibration_sensitivity(spectrum, threshold, names,
                                   [&](std::size_t, std::size_t j) { return slope[j]; });
  };
  std::optional<Eigen::VectorXd> g_modulus, g_damping;
  double sd_modulus = 0.0, sd_damping = 0.0;  // of ln E and ln λ
  if (material.youngs_modulus_sd && *material.youngs_modulus_sd > 0) {
    sd_modulus = *material.youngs_modulus_sd / material.youngs_modulus;
    g_modulus = sensitivity(log_response_slope(
        [&](double ratio) { return mechanics::rescale_modulus(modal, ratio, damping); }));
    covariance += *g_modulus * g_modulus->transpose() * sd_modulus * sd_modulus;
  }
  if (material.rayleigh_stiffness_sd && *material.rayleigh_stiffness_sd > 0 &&
      damping.stiffness > 0) {
    sd_damping = *material.rayleigh_stiffness_sd / damping.stiffness;
    g_damping = sensitivity(log_response_slope([&](double ratio) {
      return mechanics::rescale_modulus(modal, 1.0, {damping.mass, damping.stiffness * ratio});
    }));
    covariance += *g_damping * g_damping->transpose() * sd_damping * sd_damping;
  }
  if (g_modulus && g_damping)
    covariance += material.modulus_damping_correlation * sd_modulus * sd_damping *
                  (*g_modulus * g_damping->transpose() + *g_damping * g_modulus->transpose());
  return covariance;
}

}  // namespace nibrig::model::design
