// A forcing model made by hand for the design tests: tip and material curves known in closed form
// (straight lines and a bump in the knots), one surface, five frequencies, two speeds — no fit, no
// FEM. kResponse is a design's |H| at those frequencies.
#pragma once

#include <vector>

#include "model/forcing/forcing_model.hpp"
#include "model/forcing/hermite_curve.hpp"

namespace nibrig::model::design {

inline forcing::ForcingModel hand_made_model() {
  forcing::ForcingModel m;
  m.knot_frequencies_hz = forcing::default_knot_frequencies();
  const std::size_t knots = m.knot_frequencies_hz.size();
  std::vector<double> zeros(knots, 0.0), rising(knots), falling(knots), bump(knots);
  for (std::size_t k = 0; k < knots; ++k) {
    rising[k] = 0.02 * static_cast<double>(k);
    falling[k] = -0.05 * static_cast<double>(k);
    bump[k] = k == 4 ? 0.3 : 0.0;
  }
  m.tip_log_gain = {{0.001, rising}, {0.002, zeros}, {0.004, falling}};
  m.material_log_gain = {{"vero", zeros}, {"DM85", bump}, {"DM95", falling}};
  m.frequencies_hz = {10, 100, 200, 333, 490};
  m.speeds_m_s = {0.017, 0.25};
  m.surface_forcing["office"] = {{1, 2, 3, 4, 5}, {2, 4, 6, 8, 10}};
  return m;
}

inline const std::vector<double> kResponse = {0.5, 1.0, 2.0, 1.5, 0.25};

}  // namespace nibrig::model::design
