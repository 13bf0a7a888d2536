#include "model/forcing/material_calibration.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
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
  const auto each_row = [&](std::size_t g, auto&& visit) {
    for (std::size_t s = 0; s < targets[g].size(); ++s)
      for (std::size_t j = 0; j < targets[g][s].size(); ++j)
        if (std::isfinite(targets[g][s][j])) visit(s, j, targets[g][s][j]);
  };
  // The least-squares knots of the exemplars `members`, and their normal equations' QR.
  const auto solve = [&](const std::vector<std::size_t>& members) {
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    for (std::size_t g : members)
      each_row(g, [&](std::size_t, std::size_t j, double y) {
        for (const auto& [a, wa] : weights[j]) {
          rhs(static_cast<Eigen::Index>(a)) += wa * y;
          for (const auto& [b, wb] : weights[j])
            normal(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) += wa * wb;
        }
      });
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(normal);
    qr.setThreshold(1e-10);  // as the full fit: an unconstrained knot leaves a round-off pivot
    return std::pair{qr, qr.rank() == n ? Eigen::VectorXd(qr.solve(rhs)) : Eigen::VectorXd()};
  };
  std::vector<std::size_t> all(targets.size());
  for (std::size_t g = 0; g < all.size(); ++g) all[g] = g;
  // Named, not bound: clang 14 lets no lambda capture a structured binding.
  const auto solved = solve(all);
  const auto& qr = solved.first;
  const Eigen::VectorXd& theta = solved.second;
  if (theta.size() == 0)
    throw std::runtime_error(what + ": the prints leave " + std::to_string(n - qr.rank()) +
                             " of the " + std::to_string(n) +
                             " knots undetermined (no measured bins near them)");

  // Within: each exemplar's score Σ x·r at the solution, the sandwich's meat.
  std::vector<LogCells> residuals = targets;
  Eigen::MatrixXd scores = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(targets.size()), n);
  for (std::size_t g = 0; g < targets.size(); ++g)
    each_row(g, [&](std::size_t s, std::size_t j, double y) {
      double fitted = 0.0;
      for (const auto& [k, w] : weights[j]) fitted += w * theta(static_cast<Eigen::Index>(k));
      const double r = y - fitted;
      residuals[g][s][j] = r;
      for (const auto& [k, w] : weights[j])
        scores(static_cast<Eigen::Index>(g), static_cast<Eigen::Index>(k)) += w * r;
    });
  const Eigen::MatrixXd bread = qr.inverse();
  const double groups = static_cast<double>(targets.size());
  const Eigen::MatrixXd within =
      groups / (groups - 1) * bread * (scores.transpose() * scores) * bread.transpose();

  // Between prints: each print's own curve, their spread beyond what the within part explains
  // for a print's share of the exemplars, pooled over the knots.
  std::map<std::string, std::vector<std::size_t>> by_print;
  for (std::size_t g = 0; g < prints.size(); ++g) by_print[prints[g].tool].push_back(g);
  std::vector<Eigen::VectorXd> print_curves;
  std::vector<double> print_shares;  // G / G_p: how much larger a print's within variance is
  for (const auto& [tool, members] : by_print) {
    Eigen::VectorXd curve = solve(members).second;
    if (curve.size() == 0) continue;  // a print on too few bins to give a curve of its own
    print_curves.push_back(std::move(curve));
    print_shares.push_back(groups / static_cast<double>(members.size()));
  }

  MaterialCalibration out;
  out.material = material;
  out.exemplars = prints.size();
  out.prints = by_print.size();
  double tau_squared = 0.0;
  const std::size_t p = print_curves.size();
  if (p >= 2) {
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(n);
    for (const auto& c : print_curves) mean += c / static_cast<double>(p);
    double excess = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      double spread = 0.0, expected = 0.0;
      for (std::size_t i = 0; i < p; ++i) {
        spread += (print_curves[i](k) - mean(k)) * (print_curves[i](k) - mean(k));
        expected += print_shares[i] * within(k, k) / static_cast<double>(p);
      }
      excess += spread / static_cast<double>(p - 1) - expected;
    }
    tau_squared = std::max(0.0, excess / static_cast<double>(n));
  }
  out.print_log_gain_sd = std::sqrt(tau_squared);
  const double between = p >= 2 ? tau_squared / static_cast<double>(p) : 0.0;
  double within_mean = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    out.log_gain.push_back(theta(k));
    out.log_gain_within_se.push_back(std::sqrt(std::max(within(k, k), 0.0)));
    out.log_gain_se.push_back(std::sqrt(std::max(within(k, k), 0.0) + between));
    within_mean += std::max(within(k, k), 0.0) / static_cast<double>(n);
  }
  // Welch-Satterthwaite: the within part has G − 1 degrees of freedom, the between part P − 1.
  const double within_dof = groups - 1;
  out.degrees_of_freedom = between > 0 ? (within_mean + between) * (within_mean + between) /
                                             (within_mean * within_mean / within_dof +
                                              between * between / static_cast<double>(p - 1))
                                       : within_dof;
  const CalibrationResiduals fit = residual_summary(prints, residuals);
  out.residual_rms_db = fit.rms_db;
  out.print_fits = fit.per_print;
  out.model = model;
  out.model.material_log_gain[material] = out.log_gain;
  out.model.material_log_gain_se[material] = out.log_gain_se;
  out.model.notes.push_back(fmt::format(
      "material '{}' calibrated from {} prints ({} exemplars) with the surface forcing and tip "
      "curves held; log_gain_se: the exemplars' spread (cluster-robust) and the prints' "
      "({:.2f} dB between prints, pooled over the knots), {:.1f} degrees of freedom",
      material, out.prints, out.exemplars, log_gain_to_db(out.print_log_gain_sd),
      out.degrees_of_freedom));
  return out;
}

}  // namespace nibrig::model::forcing
