// How many surfaces a new material's prints must be measured on: on a catalog, a printed material
// taken as new (the model fitted without it), its curve calibrated from its prints at a few tips
// measured on only k of the surfaces, for every k, and its prints at the other tips predicted on
// every surface they were measured on. The calibration's standard error and the prediction error
// against k say what each further surface buys (material_calibration.hpp for the calibration).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"

namespace nibrig::model::forcing {

struct MaterialStudyStep {
  std::size_t surfaces = 0;   // k: the surfaces the calibration prints were measured on
  std::size_t subsets = 0;    // how many sets of k surfaces were tried
  std::size_t exemplars = 0;  // calibration exemplars per subset (the prints on k surfaces)
  // Means over the subsets: the curve's standard error (RMS over knots, dB), its exemplars' part
  // alone (what more surfaces shrink; the prints' part only more prints do), and the error of the
  // prints at the other tips predicted (dB RMS, mean over them).
  double se_rms_db = 0.0, within_se_rms_db = 0.0, prediction_rms_db = 0.0;
};

struct MaterialStudy {
  std::string material;
  std::vector<double> calibration_tips_m;
  std::vector<std::string> surfaces;     // where every calibration tip was measured
  std::size_t predicted_prints = 0;      // exemplars at the other tips
  std::vector<MaterialStudyStep> steps;  // k = 1, 2, …, surfaces
};

// Only surfaces where every calibration tip was measured are used, so that k surfaces always hold
// every tip. Subsets: all when C(n, k) ≤ max_subsets, else that many at random from `seed`. Throws
// std::invalid_argument as check_material_calibration does, and when no surface has every tip or
// no print at another tip is left to predict.
MaterialStudy study_material_calibration(std::span<const ForcingExemplar> exemplars,
                                         const std::string& material,
                                         std::span<const double> calibration_tips_m,
                                         std::size_t max_subsets = 100, unsigned seed = 1,
                                         const ForcingFitOptions& options = {});

}  // namespace nibrig::model::forcing
