// A design search in seconds: the search runs through the design-response grid (milliseconds a
// candidate), and the FEM is solved only where the grid's error could change the answer.
//
// The grid's error ε is measured, not assumed: the distance in the space between the grid's and
// the FEM's placement at the centre of each cell a contender lies in (the point farthest from the
// nodes it is interpolated from, as design_grid_error.hpp measures it). A distance to a target,
// or a group's largest or mean distance, moves by at most ε when the placement moves by ε. So a
// candidate whose grid distance exceeds the grid's best by more than 2ε cannot be nearer than the
// grid's best once both are solved: only the others (the contenders) are solved by the FEM, and the
// optimum is the nearest of them by the FEM's own distance.
#pragma once

#include <cstddef>
#include <stop_token>
#include <string>
#include <vector>

#include "model/design/design_grid_error.hpp"
#include "model/design/design_response_grid.hpp"
#include "model/design/design_search.hpp"
#include "model/space/descriptor_map.hpp"

namespace nibrig::model::design {

struct GuidedSearch {
  // The grid search's path; a contender carries the FEM's numbers in place of the grid's. Ranked by
  // those numbers: the optimum is always one the FEM solved.
  SearchResult result;
  std::vector<bool> fem_solved;     // per result.evaluated
  double grid_error = 0.0;          // ε, space units: the largest placement distance at `checks`
  std::vector<GridErrorAt> checks;  // the cell centres measured, in the order measured
  std::size_t fem_solves = 0;       // the contenders' and the checks'
};

// The cells of `grid` whose closed rectangle holds (fraction, tip): one inside a cell, two on an
// edge, up to four at a node. Indices i * (tips − 1) + j for the cell between fractions i, i + 1
// and tips j, j + 1. Empty for a point outside the grid.
std::vector<std::size_t> grid_cells_at(const GridAxes& axes, double fraction, double tip_m);

// Takes `on_grid`, a search whose candidates were evaluated through grid_predictor(setup, grid,
// surface) and placed with `map`, and solves with `by_fem` (the same evaluation through the FEM)
// the candidates that may be the optimum, measuring ε at the cells they lie in until no contender
// lies in a cell not yet measured. Solves in parallel on `threads` (0: one per core). A stop throws
// numeric::Cancelled. Throws std::invalid_argument for an empty search, a candidate whose design is
// not a mix of the grid's materials, or one with a score (its rule is not a distance ε bounds).
GuidedSearch guide_by_fem(SearchResult on_grid, const PredictionSetup& setup,
                          const DesignResponseGrid& grid, const std::string& surface,
                          const space::DescriptorMap& map, const Evaluate& by_fem,
                          unsigned threads = 0, std::stop_token stop = {});

}  // namespace nibrig::model::design
