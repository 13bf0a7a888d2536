#include "model/design/no_interpolation_baseline.hpp"

#include <algorithm>

#include "model/design/predicted_tool.hpp"
#include "model/design/tip_bracket.hpp"

namespace nibrig::model::design {

std::vector<DesignPoint> no_interpolation_corners(const forcing::ForcingModel& model,
                                                  const DesignPoint& point) {
  // The same checks as the prediction itself, so that a corner is never asked of a point that
  // cannot be predicted.
  interpolated_log_gain(model, point, model.frequencies_hz);
  const std::vector<double> tips = fitted_tips(model);
  const TipBracket b = bracket_tip(tips, point.tip_diameter_m, "the forcing model's tip curves");
  std::vector<double> corner_tips{tips[b.lower]};
  if (b.upper != b.lower) corner_tips.push_back(tips[b.upper]);
  const bool fitted_design = point.mix.size() == 1 && b.upper == b.lower;
  if (fitted_design) return {};
  std::vector<DesignPoint> corners;
  for (const auto& share : point.mix)
    for (double tip : corner_tips) corners.push_back(DesignPoint{{{share.material, 1.0}}, tip});
  return corners;
}

bool InterpolationComparison::beats_every_baseline() const {
  return !baselines.empty() &&
         std::all_of(baselines.begin(), baselines.end(),
                     [&](const BaselineError& b) { return interpolated.rms_db < b.error.rms_db; });
}

InterpolationComparison compare_with_baselines(const forcing::ForcingModel& model,
                                               const DesignPoint& point, const std::string& surface,
                                               std::span<const double> response_magnitude,
                                               const io::VelocitySpectrum& measured) {
  const auto error_with = [&](const DesignPoint& scalings) {
    return forcing::log_spectrum_error(
        predict_spectrum(model, scalings, surface, response_magnitude), measured);
  };
  InterpolationComparison out;
  out.interpolated = error_with(point);
  for (const DesignPoint& corner : no_interpolation_corners(model, point))
    out.baselines.push_back({corner, error_with(corner)});
  return out;
}

}  // namespace nibrig::model::design
