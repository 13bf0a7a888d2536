#include "model/forcing/material_calibration.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "model/forcing/calibration_prints.hpp"
#include "model/forcing/hermite_curve.hpp"

namespace nibrig::model::forcing {

namespace {

// Each print's data with the held factors (F_S, t_d) divided out: what ln m_μ must explain.
std::vector<LogCells> material_targets(const ForcingModel& model,
                                       std::span<const ForcingExemplar> prints,
                                       const std::string& material) {
  const std::string what = "calibrating material '" + material + "'";
  std::vector<LogCells> targets;
  for (const auto& p : prints) {
    if (p.material != material)
      throw std::invalid_argument(what + ": " + print_name(p) + " is of material '" + p.material +
                                  "'");
    if (!model.surface_forcing.count(p.surface))
      throw std::invalid_argument(what + ": " + print_name(p) +
                                  ": the forcing model has no surface '" + p.surface +
                                  "' (calibrate the surface first)");
    if (std::none_of(model.tip_log_gain.begin(), model.tip_log_gain.end(),
                     [&](const auto& t) { return same_tip(t.first, p.tip_diameter_m); }))
      throw std::invalid_argument(what + ": " + print_name(p) + ": the forcing model has no " +
                                  tip_label(p.tip_diameter_m) + " tip curve");
    const auto& tip = model.tip_curve(p.tip_diameter_m);
    check_print_grid(model, p, what);
    LogCells y = print_log_data(p);
    const auto& forcing = model.surface_forcing.at(p.surface);
    for (std::size_t s = 0; s < y.size(); ++s)
      for (std::size_t j = 0; j < y[s].size(); ++j)
        y[s][j] -= forcing[s][j] > 0
                       ? std::log(forcing[s][j]) +
                             hermite_value(model.knot_frequencies_hz, tip, model.frequencies_hz[j])
                       : std::numeric_limits<double>::quiet_NaN();
    targets.push_back(std::move(y));
  }
  return targets;
}

}  // namespace

MaterialCalibration calibrate_material(const ForcingModel& model,
                                       std::span<const ForcingExemplar> prints,
                                       const std::string& material) {
  const std::string what = "calibrating material '" + material + "'";
  if (material.empty()) throw std::invalid_argument("calibrating a material: no name given");
  if (model.material_log_gain.count(material))
    throw std::invalid_argument(what +
                                ": the forcing model already has a curve for it (a "
                                "calibration adds a material under a new name)");
  if (prints.size() < 2)
    throw std::invalid_argument(
        what + ": " + std::to_string(prints.size()) +
        " exemplar given; at least two (prints × surfaces) are needed for its uncertainty");
  const std::vector<LogCells> targets = material_targets(model, prints, material);

  const auto& knots = model.knot_frequencies_hz;
  const auto n = static_cast<Eigen::Index>(knots.size());
  std::vector<std::vector<std::pair<std::size_t, double>>> weights;
  for (double f : model.frequencies_hz) weights.push_back(hermite_weights(knots, f));

  // Normal equations, then each exemplar's score Σ x·r at the solution (the sandwich's meat).
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  const auto each_row = [&](auto&& visit) {
    for (std::size_t g = 0; g < targets.size(); ++g)
      for (std::size_t s = 0; s < targets[g].size(); ++s)
        for (std::size_t j = 0; j < targets[g][s].size(); ++j)
          if (std::isfinite(targets[g][s][j])) visit(g, s, j, targets[g][s][j]);
  };
  each_row([&](std::size_t, std::size_t, std::size_t j, double y) {
    for (const auto& [a, wa] : weights[j]) {
      rhs(static_cast<Eigen::Index>(a)) += wa * y;
      for (const auto& [b, wb] : weights[j])
        normal(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) += wa * wb;
    }
  });
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(normal);
  qr.setThreshold(1e-10);  // as the full fit: an unconstrained knot leaves a round-off pivot
  if (qr.rank() < n)
    throw std::runtime_error(what + ": the prints leave " + std::to_string(n - qr.rank()) +
                             " of the " + std::to_string(n) +
                             " knots undetermined (no measured bins near them)");
  const Eigen::VectorXd theta = qr.solve(rhs);

  std::vector<LogCells> residuals = targets;
  Eigen::MatrixXd scores = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(targets.size()), n);
  each_row([&](std::size_t g, std::size_t s, std::size_t j, double y) {
    double fitted = 0.0;
    for (const auto& [k, w] : weights[j]) fitted += w * theta(static_cast<Eigen::Index>(k));
    const double r = y - fitted;
    residuals[g][s][j] = r;
    for (const auto& [k, w] : weights[j])
      scores(static_cast<Eigen::Index>(g), static_cast<Eigen::Index>(k)) += w * r;
  });
  const Eigen::MatrixXd bread = qr.inverse();
  const double groups = static_cast<double>(targets.size());
  const Eigen::MatrixXd covariance =
      groups / (groups - 1) * bread * (scores.transpose() * scores) * bread.transpose();

  MaterialCalibration out;
  out.material = material;
  out.exemplars = prints.size();
  std::set<std::string> tools;
  for (const auto& p : prints) tools.insert(p.tool);
  out.prints = tools.size();
  out.degrees_of_freedom = prints.size() - 1;
  for (Eigen::Index k = 0; k < n; ++k) {
    out.log_gain.push_back(theta(k));
    out.log_gain_se.push_back(std::sqrt(std::max(covariance(k, k), 0.0)));
  }
  const CalibrationResiduals fit = residual_summary(prints, residuals);
  out.residual_rms_db = fit.rms_db;
  out.print_fits = fit.per_print;
  out.model = model;
  out.model.material_log_gain[material] = out.log_gain;
  out.model.material_log_gain_se[material] = out.log_gain_se;
  out.model.notes.push_back(
      "material '" + material + "' calibrated from " + std::to_string(out.prints) + " prints (" +
      std::to_string(out.exemplars) +
      " exemplars) with the surface forcing and tip curves held; log_gain_se: cluster-robust "
      "standard errors, an exemplar per cluster");
  return out;
}

}  // namespace nibrig::model::forcing
