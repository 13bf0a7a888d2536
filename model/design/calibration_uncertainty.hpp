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

// Whether the model carries standard errors for any of the point's materials or for the surface.
bool has_calibration_errors(const forcing::ForcingModel& model, const DesignPoint& point,
                            const std::string& surface);

}  // namespace nibrig::model::design
