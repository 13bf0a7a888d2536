// The no-interpolation baseline of Fig. 14 (the paper's grey lines): the design's own simulation —
// its |H| and the surface's F_S — with the tip and material scalings of one fitted design beside it
// instead of the interpolated ones. Interpolation earns its place when the interpolated prediction
// comes closer to a measurement of the design than every such baseline does.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "model/design/design_point.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/io/velocity_spectrum.hpp"

namespace nibrig::model::design {

// The fitted designs around `point`: every material of its mix, alone, at every fitted tip that
// brackets its tip (its own tip when that was fitted). Empty when the point is itself a fitted
// design (one material at a fitted tip): then nothing is interpolated. Throws like
// interpolated_log_gain (a tip outside the fitted ones, a material without a curve).
std::vector<DesignPoint> no_interpolation_corners(const forcing::ForcingModel& model,
                                                  const DesignPoint& point);

struct BaselineError {
  DesignPoint corner;  // whose scalings the baseline used
  forcing::SpectrumError error;
};

struct InterpolationComparison {
  forcing::SpectrumError interpolated;
  std::vector<BaselineError> baselines;  // one per corner, in the order of no_interpolation_corners
  // True when the interpolated prediction's RMS error is below every baseline's (and there is at
  // least one baseline).
  bool beats_every_baseline() const;
};

// The point's prediction (predict_spectrum with the design's |H| on the model's grid) and each
// corner's, all against `measured` (log_spectrum_error: same grid, or std::invalid_argument).
InterpolationComparison compare_with_baselines(const forcing::ForcingModel& model,
                                               const DesignPoint& point, const std::string& surface,
                                               std::span<const double> response_magnitude,
                                               const io::VelocitySpectrum& measured);

}  // namespace nibrig::model::design
