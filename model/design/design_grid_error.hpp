// How far the design-response grid's interpolation is from the full FEM prediction, measured where
// it is worst placed to be right: at every cell's centre, the point farthest from the four nodes it
// is interpolated from. Stated in what a person compares: |H| in dB, the descriptors in their own
// units (μ, log10 of the weighted vibration), and the place in the perceptual space in space units
// (one unit: 75 % preference). Set beside the descriptors' cross-validated error
// (descriptor_uncertainty.hpp), it says whether the grid is dense enough: an interpolation error
// well under the prediction's own error adds nothing a listener could hear.
#pragma once

#include <cstddef>
#include <limits>
#include <stop_token>
#include <string>
#include <vector>

#include "model/design/design_response_grid.hpp"
#include "model/space/descriptor_map.hpp"

namespace nibrig::model::design {

struct GridErrorAt {
  double fraction = 0.0, tip_m = 0.0;
  // 20·log10(|H| interpolated / |H| FEM) over the model's frequencies: RMS and largest magnitude;
  // the same for the response of the interpolated modes (what a voice runs).
  double response_rms_db = 0.0, response_max_db = 0.0;
  double modal_response_rms_db = 0.0, modal_response_max_db = 0.0;
  double first_mode_error = 0.0;  // relative: ω₁ interpolated / ω₁ FEM − 1
  std::vector<double> descriptor_error;  // interpolated − FEM, per GridError::descriptor_names
  // Distance between the two placements' means (space units); NaN without a map.
  double placement_distance = std::numeric_limits<double>::quiet_NaN();
  // The FEM prediction's own placement uncertainty, √(trace Σ / dims); NaN without a map.
  double placement_sd = std::numeric_limits<double>::quiet_NaN();
};

struct GridError {
  std::vector<std::string> descriptor_names;  // space::paper_descriptor_names(dims)
  std::vector<GridErrorAt> cells;             // one per cell centre, fraction-major
  // The worst over the cells.
  double response_rms_db = 0.0, response_max_db = 0.0, modal_response_rms_db = 0.0;
  std::vector<double> descriptor_error;  // largest |error| per descriptor
  // √ of the setup's cross-validated descriptor variance per descriptor (with friction's, as a
  // mix's μ is interpolated); empty when the setup has none.
  std::vector<double> cross_validated_sd;
  double placement_distance = std::numeric_limits<double>::quiet_NaN();
  double placement_sd = std::numeric_limits<double>::quiet_NaN();  // the smallest over the cells
};

// Predicts every cell centre both ways (predict_from_grid and predict_tool, the latter an FEM solve
// each, in parallel on `threads`), on `surface`, with descriptors of a `dims`-dimensional space
// (1-6) and, when `map` is given (with dims = its descriptor count), the placements. `progress`
// counts cells; a stop requested throws numeric::Cancelled once the cells under way are measured.
// Throws what predict_tool throws, naming the cell.
GridError measure_grid_error(const PredictionSetup& setup, const DesignResponseGrid& grid,
                             const std::string& surface, std::size_t dims,
                             const space::DescriptorMap* map = nullptr,
                             const numeric::Progress& progress = {}, std::stop_token stop = {},
                             unsigned threads = 0);

// The same at given (λ, tip) points inside the grid (`cells` then holds them in that order): to
// compare two grids at the same points, as a refinement check does.
GridError measure_grid_error_at(const PredictionSetup& setup, const DesignResponseGrid& grid,
                                const std::vector<std::pair<double, double>>& points,
                                const std::string& surface, std::size_t dims,
                                const space::DescriptorMap* map = nullptr,
                                const numeric::Progress& progress = {},
                                std::stop_token stop = {}, unsigned threads = 0);

}  // namespace nibrig::model::design
