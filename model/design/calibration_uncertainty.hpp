// What a calibration's uncertainty adds to a predicted tool's place in the perceptual space: a
// material calibrated from a few prints (its per-knot standard errors) or a surface calibrated
// from a few tools (its per-cell ones, forcing_model.hpp) moves the predicted spectrum, and so its
// vibration descriptors, by that much. The covariance is the descriptors' sensitivity (finite
// differences of the descriptors of the predicted spectrum) times those errors:
// - a calibrated material in the mix: its share of ln m at each knot, the knots taken as
//   independent (only their standard errors are stored);
// - a calibrated surface: every cell moved together by its standard error, an upper bound (the
//   pooled errors of neighbouring cells come from the same tools' spread and move together).
// Friction is not calibrated here, so its row and column are zero.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/design/design_point.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/io/velocity_spectrum.hpp"
#include "model/measure/threshold_curve.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::design {

// Over `names` (space::all_paper_descriptor_names()'s order, or any subset of it), in descriptor
// units (log10 of the weighted mean and band energies). Zero when neither the point's materials
// nor the surface carry standard errors. `spectrum` is the point's predicted spectrum on the
// model's grid (predict_spectrum). Throws std::invalid_argument for a name that is not a
// descriptor it knows.
Eigen::MatrixXd calibration_descriptor_covariance(const forcing::ForcingModel& model,
                                                  const DesignPoint& point,
                                                  const std::string& surface,
                                                  const io::VelocitySpectrum& spectrum,
                                                  const measure::ThresholdCurve& threshold,
                                                  const std::vector<std::string>& names);

// What a lab material's ring-down calibration adds for a stylus printed whole of it: its modulus
// and Rayleigh stiffness term, each known to a standard deviation with their correlation
// (mechanics::Material), move every mode (ω_i ∝ √E; ζ_i from the damping) and so |H| and the
// predicted spectrum. `modal` is the stylus's modal model at the material's values, damped by
// `damping`; the whole body being that material, a modulus ratio scales every mode alike
// (mechanics::rescale_modulus). The sensitivities are central differences in ln E and ln λ.
// Zero when the material carries no standard deviations.
Eigen::MatrixXd material_constants_covariance(const modal::ModalModel& modal,
                                              const mechanics::RayleighDamping& damping,
                                              const mechanics::Material& material,
                                              const io::VelocitySpectrum& spectrum,
                                              const measure::ThresholdCurve& threshold,
                                              const std::vector<std::string>& names);

// Whether the model carries standard errors for any of the point's materials or for the surface.
bool has_calibration_errors(const forcing::ForcingModel& model, const DesignPoint& point,
                            const std::string& surface);

}  // namespace nibrig::model::design
