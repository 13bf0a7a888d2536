#include "model/forcing/material_calibration_study.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>

#include "model/forcing/calibration_prints.hpp"
#include "model/forcing/calibration_subsets.hpp"
#include "model/forcing/material_calibration.hpp"

namespace nibrig::model::forcing {

MaterialStudy study_material_calibration(std::span<const ForcingExemplar> exemplars,
                                         const std::string& material,
                                         std::span<const double> calibration_tips_m,
                                         std::size_t max_subsets, unsigned seed,
                                         const ForcingFitOptions& options) {
  const std::string what = "studying material '" + material + "' as new";
  if (material == options.reference_material)
    throw std::invalid_argument(what + ": it is the reference material, whose curve is the gauge");
  if (calibration_tips_m.empty() || max_subsets == 0)
    throw std::invalid_argument(what + ": at least one calibration tip and one subset per step");
  const auto is_calibration_tip = [&](double d) {
    return std::any_of(calibration_tips_m.begin(), calibration_tips_m.end(),
                       [&](double t) { return same_tip(t, d); });
  };
  std::vector<ForcingExemplar> training, calibration, predicted;
  for (const auto& e : exemplars) {
    if (e.material != material)
      training.push_back(e);
    else
      (is_calibration_tip(e.tip_diameter_m) ? calibration : predicted).push_back(e);
  }
  MaterialStudy out;
  out.material = material;
  out.calibration_tips_m.assign(calibration_tips_m.begin(), calibration_tips_m.end());
  std::set<std::string> candidates;
  for (const auto& e : calibration) candidates.insert(e.surface);
  for (const auto& s : candidates)
    if (std::all_of(calibration_tips_m.begin(), calibration_tips_m.end(), [&](double t) {
          return std::any_of(calibration.begin(), calibration.end(), [&](const auto& e) {
            return e.surface == s && same_tip(e.tip_diameter_m, t);
          });
        }))
      out.surfaces.push_back(s);
  if (out.surfaces.empty())
    throw std::invalid_argument(what + ": no surface has a print of it at every calibration tip");
  if (predicted.empty())
    throw std::invalid_argument(what + ": no print of it at another tip is left to predict");
  if (const auto problems = fit_problems(training, options); !problems.empty()) {
    std::string text = what + ": the rest cannot be fitted:";
    for (const auto& p : problems) text += " " + p + ";";
    throw std::invalid_argument(text);
  }
  const ForcingModel without = fit_forcing_model(training, options);
  out.predicted_prints = predicted.size();

  std::mt19937 rng(seed);
  const std::size_t n = out.surfaces.size();
  for (std::size_t k = 1; k <= n; ++k) {
    MaterialStudyStep step;
    step.surfaces = k;
    for (const auto& subset : calibration_subsets(n, k, max_subsets, rng)) {
      std::vector<ForcingExemplar> prints;
      for (const auto& e : calibration)
        for (std::size_t i : subset)
          if (e.surface == out.surfaces[i]) prints.push_back(e);
      const MaterialCalibration c = calibrate_material(without, prints, material);
      const auto rms_db = [](const std::vector<double>& se) {
        double squares = 0.0;
        for (double x : se) squares += x * x;
        return log_gain_to_db(std::sqrt(squares / static_cast<double>(se.size())));
      };
      step.se_rms_db += rms_db(c.log_gain_se);
      step.within_se_rms_db += rms_db(c.log_gain_within_se);
      double errors = 0.0;
      for (const auto& p : prediction_errors(c.model, predicted)) errors += p.rms_db;
      step.prediction_rms_db += errors / static_cast<double>(predicted.size());
      step.exemplars = prints.size();
      ++step.subsets;
    }
    step.se_rms_db /= static_cast<double>(step.subsets);
    step.within_se_rms_db /= static_cast<double>(step.subsets);
    step.prediction_rms_db /= static_cast<double>(step.subsets);
    out.steps.push_back(step);
  }
  return out;
}

}  // namespace nibrig::model::forcing
