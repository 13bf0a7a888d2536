#include "model/forcing/surface_calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "model/forcing/calibration_prints.hpp"
#include "model/forcing/hermite_curve.hpp"

namespace nibrig::model::forcing {

namespace {

// Each tool's estimate of ln F per cell: its data with its tip and material curves divided out.
std::vector<LogCells> surface_estimates(const ForcingModel& model,
                                        std::span<const ForcingExemplar> tools,
                                        const std::string& surface) {
  const std::string what = "calibrating surface '" + surface + "'";
  std::vector<LogCells> estimates;
  std::set<std::string> seen;
  for (const auto& t : tools) {
    if (t.surface != surface)
      throw std::invalid_argument(what + ": " + print_name(t) + " was measured on another surface");
    if (!seen.insert(t.tool).second)
      throw std::invalid_argument(what + ": " + t.tool + " is given twice");
    if (std::none_of(model.tip_log_gain.begin(), model.tip_log_gain.end(),
                     [&](const auto& c) { return same_tip(c.first, t.tip_diameter_m); }))
      throw std::invalid_argument(what + ": " + print_name(t) + ": the forcing model has no " +
                                  tip_label(t.tip_diameter_m) + " tip curve");
    if (!model.material_log_gain.count(t.material))
      throw std::invalid_argument(what + ": " + print_name(t) +
                                  ": the forcing model has no curve for material '" + t.material +
                                  "'");
    check_print_grid(model, t, what);
    LogCells y = print_log_data(t);
    for (std::size_t s = 0; s < y.size(); ++s)
      for (std::size_t j = 0; j < y[s].size(); ++j) {
        const double f = model.frequencies_hz[j];
        y[s][j] -=
            model.tip_log_gain_at(t.tip_diameter_m, f) + model.material_log_gain_at(t.material, f);
      }
    estimates.push_back(std::move(y));
  }
  return estimates;
}

}  // namespace

SurfaceCalibration calibrate_surface(const ForcingModel& model,
                                     std::span<const ForcingExemplar> tools,
                                     const std::string& surface) {
  const std::string what = "calibrating surface '" + surface + "'";
  if (surface.empty()) throw std::invalid_argument("calibrating a surface: no name given");
  if (model.surface_forcing.count(surface))
    throw std::invalid_argument(what +
                                ": the forcing model already has it (a calibration adds a "
                                "surface under a new name)");
  if (tools.empty()) throw std::invalid_argument(what + ": no tools measured on it were given");
  const std::vector<LogCells> estimates = surface_estimates(model, tools, surface);

  const std::size_t speeds = model.speeds_m_s.size(), bins = model.frequencies_hz.size();
  SurfaceCalibration out;
  out.surface = surface;
  for (const auto& t : tools) out.tools.push_back(t.tool);
  std::vector<LogCells> residuals = estimates;
  // Per cell: the mean, and the squared deviations and their degrees of freedom for the pooling.
  std::vector<std::vector<double>> squares(speeds, std::vector<double>(bins, 0.0));
  std::vector<std::vector<std::size_t>> counts(speeds, std::vector<std::size_t>(bins, 0));
  out.log_forcing.assign(speeds, std::vector<double>(bins, 0.0));
  for (std::size_t s = 0; s < speeds; ++s)
    for (std::size_t j = 0; j < bins; ++j) {
      double sum = 0.0;
      std::size_t n = 0;
      for (const auto& e : estimates)
        if (std::isfinite(e[s][j])) {
          sum += e[s][j];
          ++n;
        }
      if (n == 0) {
        std::ostringstream place;
        place << what << ": at " << model.speeds_m_s[s] * 1e3 << " mm/s, "
              << model.frequencies_hz[j]
              << " Hz no tool has a positive amplitude, so its forcing is undetermined";
        throw std::invalid_argument(place.str());
      }
      const double mean = sum / static_cast<double>(n);
      out.log_forcing[s][j] = mean;
      counts[s][j] = n;
      for (auto& r : residuals)
        if (std::isfinite(r[s][j])) {
          r[s][j] -= mean;
          squares[s][j] += r[s][j] * r[s][j];
        }
    }

  if (tools.size() >= 2) {
    // Prefix sums over frequency of the squares and their degrees of freedom (cells with two or
    // more tools), so that each cell's window costs two look-ups.
    const auto& f = model.frequencies_hz;
    out.log_forcing_se.assign(speeds, std::vector<double>(bins, 0.0));
    double total = 0.0;
    for (std::size_t s = 0; s < speeds; ++s) {
      std::vector<double> square_sum(bins + 1, 0.0), dof_sum(bins + 1, 0.0);
      for (std::size_t i = 0; i < bins; ++i) {
        const bool spread = counts[s][i] >= 2;
        square_sum[i + 1] = square_sum[i] + (spread ? squares[s][i] : 0.0);
        dof_sum[i + 1] = dof_sum[i] + (spread ? static_cast<double>(counts[s][i] - 1) : 0.0);
      }
      for (std::size_t j = 0; j < bins; ++j) {
        const auto lo = static_cast<std::size_t>(
            std::lower_bound(f.begin(), f.end(), f[j] - kSurfaceSePoolHz) - f.begin());
        const auto hi = static_cast<std::size_t>(
            std::upper_bound(f.begin(), f.end(), f[j] + kSurfaceSePoolHz) - f.begin());
        const double dof = dof_sum[hi] - dof_sum[lo];
        const double se = dof > 0 ? std::sqrt((square_sum[hi] - square_sum[lo]) / dof /
                                              static_cast<double>(counts[s][j]))
                                  : 0.0;
        out.log_forcing_se[s][j] = se;
        total += se * se;
      }
    }
    out.rms_se_db = log_gain_to_db(std::sqrt(total / static_cast<double>(speeds * bins)));
  }
  const CalibrationResiduals fit = residual_summary(tools, residuals);
  out.residual_rms_db = fit.rms_db;
  out.tool_fits = fit.per_print;

  out.model = model;
  auto& forcing = out.model.surface_forcing[surface];
  for (const auto& row : out.log_forcing) {
    forcing.emplace_back();
    for (double l : row) forcing.back().push_back(std::exp(l));
  }
  if (!out.log_forcing_se.empty()) out.model.surface_log_forcing_se[surface] = out.log_forcing_se;
  out.model.notes.push_back(fmt::format(
      "surface '{}' calibrated from {} tools the model knows, their tip and material curves "
      "held; {}",
      surface, tools.size(),
      tools.size() >= 2
          ? fmt::format("log_forcing_se: the tools' spread pooled over ±{:g} Hz, over √n",
                        kSurfaceSePoolHz)
          : std::string("one tool: no uncertainty")));
  return out;
}

}  // namespace nibrig::model::forcing
