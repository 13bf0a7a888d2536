// A design-response grid made by hand for the design tests: its nodes' responses and modes are
// bilinear in (λ, tip in mm), so interpolation must reproduce them to rounding; with prediction
// inputs holding the hand-made forcing model it predicts a design in milliseconds, no FEM, no fit.
#pragma once

#include <cmath>
#include <memory>

#include "model/design/design_response_grid.hpp"
#include "model/design/prediction_inputs.hpp"
#include "tests/model/design/hand_made_forcing_model.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design::grid_testing {

// Bilinear in (λ, tip in mm): interpolation inside a cell reproduces these exactly.
inline double bilinear(double a, double b, double c, double d, double fraction, double tip_m) {
  const double t = tip_m * 1e3;
  return a + b * fraction + c * t + d * fraction * t;
}

inline DesignResponseGrid synthetic_grid() {
  DesignResponseGrid grid;
  grid.axes = {"vero", "DM85", {0.0, 0.5, 1.0}, {0.001, 0.002, 0.004}};
  grid.frequencies_hz = hand_made_model().frequencies_hz;
  grid.mesh_size_m = 0.003;
  grid.modes = 3;
  for (double fraction : grid.axes.fractions)
    for (double tip : grid.axes.tips_m) {
      SimulatedResponse node;
      node.design_name = "node " + to_string(grid_point(grid.axes, fraction, tip));
      for (std::size_t j = 0; j < grid.frequencies_hz.size(); ++j)
        node.response_magnitude.push_back(
            std::exp(bilinear(0.1 * j, -0.3, 0.2, 0.05 * j, fraction, tip)));
      for (int k = 0; k < grid.modes; ++k) {
        node.modal.omega.push_back(std::exp(bilinear(5.0 + k, -0.1, 0.02, 0.01, fraction, tip)));
        node.modal.zeta.push_back(bilinear(0.01, 0.02, 0.001, 0.0, fraction, tip));
        node.modal.input.push_back(1.0);
        // Mode 1's gain changes sign across λ: a jump between nodes, counted.
        node.modal.output.push_back(k == 1 ? bilinear(-0.5, 1.5, 0.0, 0.0, fraction, tip)
                                           : bilinear(1.0 + k, 0.5, 0.1, 0.0, fraction, tip));
      }
      grid.nodes.push_back(node);
    }
  return grid;
}

// The prediction inputs a cache key is made from, with a hand-made model: no FEM, no fit.
inline std::unique_ptr<PredictionInputs> hand_made_inputs() {
  forcing::ForcingInputOptions options;
  options.catalog = nibrig::test::assets_dir() / "default_catalog.json";
  options.mesh_size = 0.004;
  options.modes = 8;
  return load_prediction_inputs(options, "", hand_made_model());
}

}  // namespace nibrig::model::design::grid_testing
