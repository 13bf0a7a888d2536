#include "model/forcing/surface_calibration_study.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>

#include "model/forcing/calibration_prints.hpp"
#include "model/forcing/calibration_subsets.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/forcing/surface_calibration.hpp"

namespace nibrig::model::forcing {

std::optional<std::size_t> SurfaceStudy::fewest_tools_within(double db) const {
  for (const auto& step : steps)
    if (step.prediction_rms_db <= db) return step.tools;
  return std::nullopt;
}

std::optional<std::size_t> SurfaceStudy::fewest_tools_se_within(double db) const {
  for (const auto& step : steps)
    if (step.tools >= 2 && step.se_rms_db <= db) return step.tools;
  return std::nullopt;
}

SurfaceStudy study_surface_calibration(std::span<const ForcingExemplar> exemplars,
                                       const std::string& surface, std::size_t max_subsets,
                                       unsigned seed, const ForcingFitOptions& options) {
  const std::string what = "treating surface '" + surface + "' as new";
  if (max_subsets == 0) throw std::invalid_argument(what + ": at least one subset per step");
  std::vector<ForcingExemplar> training;
  std::vector<std::size_t> on_surface;
  for (std::size_t e = 0; e < exemplars.size(); ++e)
    if (exemplars[e].surface == surface)
      on_surface.push_back(e);
    else
      training.push_back(exemplars[e]);
  if (const auto problems = fit_problems(training, options); !problems.empty()) {
    std::string text = what + ": the rest cannot be fitted:";
    for (const auto& p : problems) text += " " + p + ";";
    throw std::invalid_argument(text);
  }
  const ForcingModel without = fit_forcing_model(training, options);
  // The tools the model without the surface can predict (its tip and material are there).
  std::vector<std::size_t> known;
  for (std::size_t e : on_surface) {
    const auto& x = exemplars[e];
    const bool tip =
        std::any_of(without.tip_log_gain.begin(), without.tip_log_gain.end(),
                    [&](const auto& t) { return same_tip(t.first, x.tip_diameter_m); });
    if (tip && without.material_log_gain.count(x.material)) known.push_back(e);
  }
  if (known.size() < 2)
    throw std::invalid_argument(what + ": " + std::to_string(known.size()) +
                                " of its tools are known to the model without it; two are needed "
                                "(one to calibrate from, one to predict)");

  SurfaceStudy out;
  out.surface = surface;
  const ForcingModel full = fit_forcing_model(exemplars, options);
  const LeaveOneOut loo = leave_one_out(exemplars, known, options);
  for (std::size_t i = 0; i < known.size(); ++i) {
    out.tools.push_back(exemplars[known[i]].tool);
    out.full_fit_rms_db.push_back(full.exemplar_fits[known[i]].rms_db);
    if (!loo.results[i].predictable)
      throw std::invalid_argument(what + ": " + out.tools.back() +
                                  " cannot be left out of the full fit: " + loo.results[i].reason);
    out.full_loo_rms_db.push_back(loo.results[i].rms_db);
  }
  const auto mean = [](const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  };
  out.mean_full_fit_db = mean(out.full_fit_rms_db);
  out.mean_full_loo_db = mean(out.full_loo_rms_db);

  std::mt19937 rng(seed);
  const std::size_t n = known.size();
  for (std::size_t k = 1; k < n; ++k) {
    SurfaceStudyStep step;
    step.tools = k;
    std::vector<double> tool_sum(n, 0.0);
    std::vector<std::size_t> tool_count(n, 0);
    double total = 0.0;
    std::size_t total_count = 0;
    for (const auto& subset : calibration_subsets(n, k, max_subsets, rng)) {
      std::vector<ForcingExemplar> reference;
      for (std::size_t i : subset) reference.push_back(exemplars[known[i]]);
      const SurfaceCalibration calibration = calibrate_surface(without, reference, surface);
      double subset_sum = 0.0;
      std::size_t subset_count = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (std::binary_search(subset.begin(), subset.end(), i)) continue;
        const ForcingExemplar& x = exemplars[known[i]];
        const double db =
            log_spectrum_error(calibration.model.predict(x.response_magnitude, surface,
                                                         x.tip_diameter_m, x.material),
                               x.measured)
                .rms_db;
        tool_sum[i] += db;
        ++tool_count[i];
        subset_sum += db;
        ++subset_count;
      }
      total += subset_sum;
      total_count += subset_count;
      step.worst_subset_rms_db =
          std::max(step.worst_subset_rms_db, subset_sum / static_cast<double>(subset_count));
      step.se_rms_db += calibration.rms_se_db;
      ++step.subsets;
    }
    step.prediction_rms_db = total / static_cast<double>(total_count);
    step.se_rms_db /= static_cast<double>(step.subsets);
    for (std::size_t i = 0; i < n; ++i)
      step.tool_rms_db.push_back(
          tool_count[i] > 0 ? tool_sum[i] / static_cast<double>(tool_count[i]) : std::nan(""));
    out.steps.push_back(std::move(step));
  }
  return out;
}

SurfaceCalibration calibrate_held_out_surface(std::span<const ForcingExemplar> exemplars,
                                              const std::string& surface,
                                              std::span<const std::string> tools,
                                              const measure::ThresholdCurve* threshold,
                                              const ForcingFitOptions& options) {
  const auto reference = tools_on_surface(exemplars, surface, tools);
  std::vector<ForcingExemplar> training;
  for (const auto& e : exemplars)
    if (e.surface != surface) training.push_back(e);
  ForcingModel without = fit_forcing_model(training, options);
  if (threshold) {
    without.held_out_descriptor_errors = held_out_descriptor_errors(training, *threshold, options);
    without.descriptor_error_threshold = threshold->source();
  }
  return calibrate_surface(without, reference, surface);
}

}  // namespace nibrig::model::forcing
