#include "model/forcing/material_calibration_check.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/forcing/leave_one_out.hpp"

namespace nibrig::model::forcing {

namespace {

// RMS over the model's cells of the standard error of a prediction, in dB.
double material_prediction_se_db(const ForcingModel& model, const ForcingExemplar& e) {
  double sum = 0.0;
  for (std::size_t s = 0; s < model.speeds_m_s.size(); ++s)
    for (std::size_t j = 0; j < model.frequencies_hz.size(); ++j) {
      const double se = model.prediction_log_se(e.surface, e.material, s, j);
      sum += se * se;
    }
  return log_gain_to_db(
      std::sqrt(sum / static_cast<double>(model.speeds_m_s.size() * model.frequencies_hz.size())));
}

}  // namespace

MaterialCalibrationCheck check_material_calibration(std::span<const ForcingExemplar> exemplars,
                                                    const std::string& material,
                                                    std::span<const double> calibration_tips_m,
                                                    const ForcingFitOptions& options,
                                                    const measure::ThresholdCurve* threshold) {
  const std::string what = "treating material '" + material + "' as new";
  if (material == options.reference_material)
    throw std::invalid_argument(what + ": it is the reference material, whose curve is the gauge");
  const auto is_calibration_tip = [&](double d) {
    return std::any_of(calibration_tips_m.begin(), calibration_tips_m.end(),
                       [&](double t) { return same_tip(t, d); });
  };
  std::vector<ForcingExemplar> training, calibration;
  std::vector<std::size_t> held;
  for (std::size_t e = 0; e < exemplars.size(); ++e) {
    if (exemplars[e].material != material) {
      training.push_back(exemplars[e]);
      continue;
    }
    held.push_back(e);
    if (is_calibration_tip(exemplars[e].tip_diameter_m)) calibration.push_back(exemplars[e]);
  }
  if (held.empty()) throw std::invalid_argument(what + ": no exemplar is of that material");
  for (double t : calibration_tips_m)
    if (std::none_of(calibration.begin(), calibration.end(),
                     [&](const auto& e) { return same_tip(e.tip_diameter_m, t); }))
      throw std::invalid_argument(what + ": no print of it has a " + tip_label(t) + " tip");
  if (const auto problems = fit_problems(training, options); !problems.empty()) {
    std::string text = what + ": the rest cannot be fitted:";
    for (const auto& p : problems) text += " " + p + ";";
    throw std::invalid_argument(text);
  }

  MaterialCalibrationCheck out;
  out.material = material;
  out.calibration_tips_m.assign(calibration_tips_m.begin(), calibration_tips_m.end());
  ForcingModel without = fit_forcing_model(training, options);
  if (threshold) {
    without.held_out_descriptor_errors = held_out_descriptor_errors(training, *threshold, options);
    without.descriptor_error_threshold = threshold->source();
  }
  out.calibration = calibrate_material(without, calibration, material);
  const ForcingModel full = fit_forcing_model(exemplars, options);
  out.full_fit_log_gain = full.material_curve(material);
  const LeaveOneOut loo = leave_one_out(exemplars, held, options);
  const ForcingModel& calibrated = out.calibration.model;
  for (std::size_t k = 0; k < held.size(); ++k) {
    const ForcingExemplar& e = exemplars[held[k]];
    CalibratedPrintError p;
    p.tool = e.tool;
    p.surface = e.surface;
    p.tip_diameter_m = e.tip_diameter_m;
    p.calibration_print = is_calibration_tip(e.tip_diameter_m);
    p.calibrated_rms_db = log_spectrum_error(calibrated.predict(e.response_magnitude, e.surface,
                                                                e.tip_diameter_m, material),
                                             e.measured)
                              .rms_db;
    p.uncalibrated_rms_db =
        log_spectrum_error(calibrated.predict(e.response_magnitude, e.surface, e.tip_diameter_m,
                                              calibrated.reference_material),
                           e.measured)
            .rms_db;
    p.full_fit_rms_db = full.exemplar_fits[held[k]].rms_db;
    if (!loo.results[k].predictable)
      throw std::invalid_argument(what + ": " + e.tool + " on " + e.surface +
                                  " cannot be left out of the full fit: " + loo.results[k].reason);
    p.full_loo_rms_db = loo.results[k].rms_db;
    p.predicted_se_db = material_prediction_se_db(calibrated, e);
    if (!p.calibration_print) {
      out.mean_calibrated_db += p.calibrated_rms_db;
      out.mean_uncalibrated_db += p.uncalibrated_rms_db;
      out.mean_full_fit_db += p.full_fit_rms_db;
      out.mean_full_loo_db += p.full_loo_rms_db;
      ++out.predicted;
    }
    out.prints.push_back(std::move(p));
  }
  if (out.predicted > 0) {
    const auto n = static_cast<double>(out.predicted);
    out.mean_calibrated_db /= n;
    out.mean_uncalibrated_db /= n;
    out.mean_full_fit_db /= n;
    out.mean_full_loo_db /= n;
  }
  return out;
}

}  // namespace nibrig::model::forcing
