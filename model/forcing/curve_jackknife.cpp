#include "model/forcing/curve_jackknife.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

namespace nibrig::model::forcing {

namespace {

CurveReplicate curves_of(const ForcingModel& model) {
  return CurveReplicate{model.tip_log_gain, model.material_log_gain};
}

// Why a replicate without `tool` cannot stand beside the full fit: a curve of the full fit that it
// lacks (the tool was the only one with that tip or material). Empty when it can.
std::string missing_curve(const CurveReplicate& full, const CurveReplicate& replicate) {
  for (const auto& [d, knots] : full.tip)
    if (replicate.tip.count(d) == 0) return "no other tool has the " + tip_label(d) + " tip";
  for (const auto& [m, knots] : full.material)
    if (replicate.material.count(m) == 0) return "no other tool is of " + m;
  return {};
}

}  // namespace

CurveJackknife jackknife_curves(std::span<const ForcingExemplar> exemplars,
                                const ForcingFitOptions& options) {
  CurveJackknife out;
  const ForcingModel model = fit_forcing_model(exemplars, options);
  out.full = curves_of(model);
  out.knot_frequencies_hz = model.knot_frequencies_hz;
  const CurveReplicate& full = out.full;
  std::set<std::string> tools;
  for (const auto& e : exemplars) tools.insert(e.tool);

  for (const std::string& tool : tools) {
    std::vector<ForcingExemplar> rest;
    for (const auto& e : exemplars)
      if (e.tool != tool) rest.push_back(e);
    if (const auto problems = fit_problems(rest, options); !problems.empty()) {
      out.not_left_out.push_back(tool + ": " + problems.front());
      continue;
    }
    CurveReplicate replicate = curves_of(fit_forcing_model(rest, options));
    if (const std::string why = missing_curve(full, replicate); !why.empty()) {
      out.not_left_out.push_back(tool + ": " + why);
      continue;
    }
    out.tools.push_back(tool);
    out.replicates.push_back(std::move(replicate));
  }
  return out;
}

double CurveJackknife::standard_error(
    const std::function<double(const CurveReplicate&)>& statistic) const {
  const std::size_t n = replicates.size();
  if (n < 2)
    throw std::invalid_argument("jackknife: " + std::to_string(n) +
                                " replicate(s); a standard error needs at least two");
  std::vector<double> values;
  double mean = 0.0;
  for (const auto& r : replicates) {
    values.push_back(statistic(r));
    mean += values.back();
  }
  mean /= static_cast<double>(n);
  double sum = 0.0;
  for (double v : values) sum += (v - mean) * (v - mean);
  return std::sqrt(static_cast<double>(n - 1) / static_cast<double>(n) * sum);
}

std::vector<double> CurveJackknife::tip_standard_errors(double tip_diameter_m) const {
  std::vector<double> se;
  if (replicates.empty()) return se;
  const auto knot_of = [&](const CurveReplicate& r) -> const std::vector<double>& {
    for (const auto& [d, knots] : r.tip)
      if (same_tip(d, tip_diameter_m)) return knots;
    throw std::invalid_argument("jackknife: no tip curve for " + tip_label(tip_diameter_m));
  };
  for (std::size_t k = 0; k < knot_of(replicates.front()).size(); ++k)
    se.push_back(standard_error([&](const CurveReplicate& r) { return knot_of(r)[k]; }));
  return se;
}

std::vector<double> CurveJackknife::material_standard_errors(const std::string& material) const {
  std::vector<double> se;
  if (replicates.empty()) return se;
  const auto knot_of = [&](const CurveReplicate& r) -> const std::vector<double>& {
    const auto it = r.material.find(material);
    if (it == r.material.end())
      throw std::invalid_argument("jackknife: no material curve for " + material);
    return it->second;
  };
  for (std::size_t k = 0; k < knot_of(replicates.front()).size(); ++k)
    se.push_back(standard_error([&](const CurveReplicate& r) { return knot_of(r)[k]; }));
  return se;
}

}  // namespace nibrig::model::forcing
