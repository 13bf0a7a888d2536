// Where a tip diameter lies among the fitted (or measured) ones: shared by the interpolation of the
// scalings and friction, and by the no-interpolation baseline that names the neighbours.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "model/forcing/forcing_model.hpp"

namespace nibrig::model::design {

// The two neighbours of d among ascending `diameters` and the weight of the upper; lower == upper
// (weight 0) when d is one of them. Throws std::invalid_argument when d lies outside them, saying
// by how far: `what` names the curves or measurements in the message.
struct TipBracket {
  std::size_t lower = 0, upper = 0;
  double weight = 0.0;
};
TipBracket bracket_tip(const std::vector<double>& diameters, double d, const std::string& what);

// The tip diameters a forcing model has curves for, ascending.
std::vector<double> fitted_tips(const forcing::ForcingModel& model);

}  // namespace nibrig::model::design
