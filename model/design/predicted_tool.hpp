// Predicting a design that was never printed (Sec. 5.3): its simulated response |H| times the
// surface's fitted forcing F_S times the tip and material scalings, interpolated between the
// fitted ones; its friction interpolated between the measured printed tools; its descriptors
// computed as for a measurement, so it can sit in the catalog and the perceptual space beside
// measured tools.
//
// Interpolation, as the paper does it (linearly): ln t at a tip diameter between two fitted tips is
// linear in the diameter between them; ln m of a mix is the fractions' weighted sum of the
// materials' ln m; μ is linear in the diameter between measured tips of each material on the
// surface, then weighted by the fractions. Nothing is extrapolated: a tip outside the fitted (or,
// for μ, measured) diameters is refused, saying by how far — the curves are fitted from three tips,
// and a straight line beyond them would be a guess with nothing to check it against.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "model/design/descriptor_uncertainty.hpp"
#include "model/design/design_point.hpp"
#include "model/design/mixed_design.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/io/catalog_file.hpp"
#include "model/measure/descriptors.hpp"
#include "model/measure/threshold_curve.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::design {

// ln t(f) + ln m(f) of the point at each frequency. Throws std::invalid_argument for a tip outside
// the fitted tips (naming the distance and the range) or a material without a fitted curve.
std::vector<double> interpolated_log_gain(const forcing::ForcingModel& model,
                                          const DesignPoint& point,
                                          std::span<const double> frequencies_hz);

// |H|·F_S·t·m on the model's grid, |H| given per model frequency. Throws like
// interpolated_log_gain and ForcingModel::predict (unknown surface, wrong |H| length).
io::VelocitySpectrum predict_spectrum(const forcing::ForcingModel& model, const DesignPoint& point,
                                      const std::string& surface,
                                      std::span<const double> response_magnitude);

// μ of the point on `surface` from the catalog's printed tools (not their nail-test variants);
// `measured` when it is one printed tool's measured μ (one material, a measured tip diameter)
// rather than an interpolation. Throws std::invalid_argument when a material of the mix has no
// measured friction on the surface, or the tip lies outside the diameters measured for it there
// (saying by how far).
struct FrictionPrediction {
  double mu = 0.0;
  bool measured = false;
};
FrictionPrediction interpolated_friction(const io::Catalog& catalog, const DesignPoint& point,
                                         const std::string& surface);

struct PredictionSetup {
  const forcing::ForcingModel* model = nullptr;
  const io::Catalog* catalog = nullptr;  // for μ
  mechanics::Design template_design;     // the printed tools' stylus (assets/designs)
  mechanics::MaterialTable materials;
  const measure::ThresholdCurve* threshold = nullptr;  // weights the descriptors, as the catalog
  // The predictions' cross-validated descriptor error; null: none known, placed as if measured.
  const DescriptorErrorCovariance* descriptor_errors = nullptr;
  double mesh_size = 0.0;  // m; 0 keeps the template's
  int modes = 0;           // 0 keeps the template's
};

struct PredictedTool {
  DesignPoint point;
  std::string surface;
  std::string design_name;
  double first_mode_hz = 0.0;
  modal::ModalModel modal;                 // the design's modes: what a real-time voice runs
  std::vector<double> response_magnitude;  // |H| at the model's frequencies
  io::VelocitySpectrum spectrum;
  double mu = 0.0;
  measure::VibrationDescriptors vibration;
  // The error its descriptors carry (setup's, without friction when μ was measured), plus what a
  // calibrated material or surface adds (calibration_uncertainty.hpp); empty when there is none.
  DescriptorErrorCovariance descriptor_errors;
  // What the design's materials stand on, its least calibrated one's (mechanics::Material::basis:
  // "fitted", "datasheet", "estimate"; "" when the table does not say).
  std::string material_basis;
};

// Meshes and solves the point's design (mixed_design.hpp), or `own_design` when given (a
// designer's stylus file, its point from design_point_of), then predicts as above.
PredictedTool predict_tool(const PredictionSetup& setup, const DesignPoint& point,
                           const std::string& surface,
                           const mechanics::Design* own_design = nullptr);

// predict_tool in its two steps, for callers that get the stylus's response elsewhere (the
// design-response grid interpolates it): the FEM step, the slow one, and everything after it,
// which is cheap. predict_tool(setup, p, s) equals predict_from_response(setup, p, s,
// simulate_response(setup, p)) exactly.
struct SimulatedResponse {
  std::string design_name;
  modal::ModalModel modal;                 // the design's modes
  std::vector<double> response_magnitude;  // |H| at the model's frequencies
};
// The stylus a prediction with `setup` solves for `point`: mixed_design, at the setup's mesh size
// and modes where it gives them. What the export prints is this same design. Throws what
// mixed_design throws.
MixedDesign solved_design(const PredictionSetup& setup, const DesignPoint& point);
// Throws what mixed_design and build_design_model throw.
SimulatedResponse simulate_response(const PredictionSetup& setup, const DesignPoint& point,
                                    const mechanics::Design* own_design = nullptr);
// Throws like predict_tool's cheap checks (tip out of range, unknown surface or material, no
// friction) and for a response of the wrong length.
PredictedTool predict_from_response(const PredictionSetup& setup, const DesignPoint& point,
                                    const std::string& surface, SimulatedResponse response);

// The catalog entries of a predicted tool (kind "predicted", id "pred:<point>"), so that it is
// described and placed like any measured tool.
io::ToolEntry predicted_tool_entry(const PredictedTool& tool);
io::Pairing predicted_pairing(const PredictedTool& tool, const std::string& threshold_name);

}  // namespace nibrig::model::design
