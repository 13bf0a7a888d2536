// How many reference tools a new surface takes: on a catalog, one surface is taken as new, the
// model fitted without it, and its forcing calibrated (surface_calibration.hpp) from k of the tools
// measured on it, for every k from 1 to all but one; each time the tools left out are predicted on
// it. Their error against k, beside the same tools' error under the model fitted on everything,
// says when a calibration is as good as the measurement's repeatability lets any be.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/surface_calibration.hpp"
#include "model/measure/threshold_curve.hpp"

namespace nibrig::model::forcing {

struct SurfaceStudyStep {
  std::size_t tools = 0;    // k: the reference tools calibrated from
  std::size_t subsets = 0;  // how many sets of k tools were tried
  // Mean over the subsets and the tools each leaves out of the prediction error, dB RMS, and the
  // worst subset's mean.
  double prediction_rms_db = 0.0, worst_subset_rms_db = 0.0;
  // Mean over the subsets of the calibration's standard error of ln F (RMS over cells, dB): 0 for
  // k = 1, where there is no spread to tell it.
  double se_rms_db = 0.0;
  // Per tool (SurfaceStudy::tools), its mean error over the subsets that leave it out.
  std::vector<double> tool_rms_db;
};

struct SurfaceStudy {
  std::string surface;
  std::vector<std::string> tools;       // measured on the surface, known to the model without it
  std::vector<double> full_fit_rms_db;  // per tool: the model fitted on every exemplar
  std::vector<double> full_loo_rms_db;  // per tool: the model fitted on every other exemplar
  double mean_full_fit_db = 0.0, mean_full_loo_db = 0.0;
  std::vector<SurfaceStudyStep> steps;  // k = 1, 2, …, tools − 1
  // The fewest reference tools whose held-out tools are predicted within `db` on the mean, if any.
  std::optional<std::size_t> fewest_tools_within(double db) const;
  // The fewest reference tools whose calibration's standard error (RMS over cells) is within `db`,
  // if any (from two: one tool has no spread to tell it).
  std::optional<std::size_t> fewest_tools_se_within(double db) const;
};

// Subsets of k tools: all of them when there are at most `max_subsets`, else that many drawn at
// random (distinct, from `seed`), so that the study's cost stays bounded. Throws
// std::invalid_argument naming the surface: fewer than two of its tools known to the model without
// it, or the rest not fittable (fit_problems).
SurfaceStudy study_surface_calibration(std::span<const ForcingExemplar> exemplars,
                                       const std::string& surface, std::size_t max_subsets = 200,
                                       unsigned seed = 1, const ForcingFitOptions& options = {});

// The surface calibrated from the tools named (all measured on it when none are) against the model
// fitted to every exemplar not on it: what a study's calibration is written as. With a threshold
// curve that model carries its held-out descriptor errors (forcing_inputs.hpp). Throws as
// tools_on_surface, fit_forcing_model and calibrate_surface do.
SurfaceCalibration calibrate_held_out_surface(std::span<const ForcingExemplar> exemplars,
                                              const std::string& surface,
                                              std::span<const std::string> tools = {},
                                              const measure::ThresholdCurve* threshold = nullptr,
                                              const ForcingFitOptions& options = {});

}  // namespace nibrig::model::forcing
