// The material calibration checked on measured prints: one printed material of a catalog is taken
// as new, the model fitted without it, its curve calibrated from the prints of a few tips only
// (material_calibration.hpp), and every recorded print of it predicted. Each error stands beside
// the same print's error under the model fitted on everything (in sample, and with the print left
// out): what calibrating from a few prints costs against having measured them all.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/material_calibration.hpp"
#include "model/measure/threshold_curve.hpp"

namespace nibrig::model::forcing {

struct CalibratedPrintError {
  std::string tool, surface;
  double tip_diameter_m = 0.0;
  bool calibration_print = false;  // the curve was calibrated from it: its error is in sample
  double calibrated_rms_db = 0.0;  // the calibrated model's prediction against the measurement
  // The same model without calibrating: the material taken as the reference (m ≡ 1), the
  // prediction a lab has before any print. What the calibration must beat.
  double uncalibrated_rms_db = 0.0;
  double full_fit_rms_db = 0.0;  // the model fitted on every exemplar, this one among them
  double full_loo_rms_db = 0.0;  // the model fitted on every other exemplar (leave one out)
  // RMS over the cells of the prediction's standard error from the calibration, in dB.
  double predicted_se_db = 0.0;
};

struct MaterialCalibrationCheck {
  std::string material;
  std::vector<double> calibration_tips_m;
  MaterialCalibration calibration;           // against the model fitted without the material
  std::vector<double> full_fit_log_gain;     // the material's curve in the fit of everything
  std::vector<CalibratedPrintError> prints;  // every exemplar of the material, catalog order
  // Means over the prints not calibrated from (the predictions proper), dB RMS.
  double mean_calibrated_db = 0.0, mean_uncalibrated_db = 0.0, mean_full_fit_db = 0.0,
         mean_full_loo_db = 0.0;
  std::size_t predicted = 0;
};

// Throws std::invalid_argument naming the material or tips: no exemplar of the material, no
// calibration print at a tip asked for, the reference material (its curve is the gauge), or the
// rest not fittable without it (fit_problems). With a threshold curve, the model calibrated against
// carries the held-out descriptor errors of its exemplars, as every model predictions are placed
// with (forcing_inputs.hpp).
MaterialCalibrationCheck check_material_calibration(
    std::span<const ForcingExemplar> exemplars, const std::string& material,
    std::span<const double> calibration_tips_m, const ForcingFitOptions& options = {},
    const measure::ThresholdCurve* threshold = nullptr);

}  // namespace nibrig::model::forcing
