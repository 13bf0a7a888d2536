// Predictions of a design as fast as a slider moves: a full prediction meshes and solves the
// stylus, far too slow to follow one. So everything of a design that needs the FEM — its response
// |H| on the forcing model's grid and its modes — is computed once over a grid of (mix fraction λ
// between two materials, tip diameter), and any point inside the grid is interpolated from the four
// nodes around it; the rest of a prediction (spectrum, μ, descriptors, placement) is cheap and done
// exactly as predict_tool does it.
//
// What is interpolated, bilinearly in (λ, tip) inside a cell:
// - ln|H| at each frequency (|H| spans decades; its logarithm varies far more evenly);
// - each mode's ln ω, its damping ratio ζ and its gain g = b·c, mode by mode in frequency order.
//   Only the product b·c reaches the sensor (every response and integrator is linear in b and in c,
//   and a mode shape's sign is arbitrary, so b and c alone may flip sign between nodes while their
//   product does not); the interpolated mode carries b = √|g|, c = sign(g)·√|g|.
// Modes are matched by their rank in frequency. Two modes that swap rank between two nodes (a
// crossing: the stylus's near-degenerate bending pairs in x and y do it) are then blended rather
// than followed. Where the gain of a rank changes sign or by more than kGainJump between
// neighbouring nodes the grid counts it (mode_jumps) and says so in the log; the blend is kept,
// because for a near-degenerate pair the two blended ranks sit at nearly one frequency and their
// gains add up to the pair's, so the response is nearly right, while following one mode through a
// crossing would need its shape, which the modal model does not keep. The spectrum, descriptors and
// placement never depend on this matching: they use the interpolated ln|H|. The grid's error
// (design_grid_error.hpp) measures the interpolated modes' own response against the FEM as well.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "model/design/design_point.hpp"
#include "model/design/predicted_tool.hpp"
#include "model/numeric/progress_counter.hpp"

namespace nibrig::model::design {

struct GridAxes {
  std::string material_a, material_b;  // λ is the fraction of material_b; 1 − λ that of material_a
  std::vector<double> fractions;       // λ at the nodes: strictly increasing, inside [0, 1]
  std::vector<double> tips_m;          // tip diameter at the nodes: strictly increasing, > 0
};

// n_λ fractions evenly over [0, 1] and n_tip tips evenly over [min_tip_m, max_tip_m], ends included.
GridAxes even_axes(const std::string& material_a, const std::string& material_b,
                   std::size_t fraction_points, double min_tip_m, double max_tip_m,
                   std::size_t tip_points);

// The default density: 5 fractions (steps of 0.25) × 7 tips (0.5 mm) over the forcing model's
// fitted tips 1-4 mm, 35 FEM solves (slow enough to show a coarse grid first: coarse_axes below).
// Its interpolation error at every cell centre is a small fraction of the predictions' own
// cross-validated error (bench DesignGridError), so a denser grid would buy nothing a listener or
// the space could tell.
inline constexpr std::size_t kDefaultFractionPoints = 5, kDefaultTipPoints = 7;

// The grid to show while a fine grid is solved: on each axis the fine nodes at every other index,
// both ends kept, n/2 + 1 of the n (5 × 7 → 3 × 4: 12 of the 35 solves; an axis of 2 or 3 keeps
// its ends). An even count cannot halve evenly; its inner nodes are the nearest to an even spread.
// Every coarse node is a fine node, the same doubles, so the fine grid reuses its solve (`known`
// below) and costs only the rest (23 of 35).
GridAxes coarse_axes(const GridAxes& fine);

// Throws std::invalid_argument naming the axis and the entry: fewer than 2 nodes on an axis, values
// out of order or out of range, equal or empty materials.
void validate(const GridAxes& axes);

// The design at (λ, tip): material_a with 1 − λ and material_b with λ, a zero fraction dropped.
DesignPoint grid_point(const GridAxes& axes, double fraction, double tip_m);

// A gain is said to jump between neighbouring nodes when it changes sign, or its magnitude changes
// by more than this factor, while it is above kSignificantGain of the largest gain at either node.
inline constexpr double kGainJump = 10.0, kSignificantGain = 1e-3;

struct DesignResponseGrid {
  GridAxes axes;
  std::vector<double> frequencies_hz;  // the forcing model's grid |H| is given on
  double mesh_size_m = 0.0;            // as solved (the setup's, else the template's)
  int modes = 0;
  // Node (i, j) at fractions[i], tips_m[j] is nodes[i * tips_m.size() + j].
  std::vector<SimulatedResponse> nodes;
  std::size_t mode_jumps = 0;  // rank-matched modes whose gain jumps between neighbours (above)

  const SimulatedResponse& node(std::size_t fraction_index, std::size_t tip_index) const {
    return nodes.at(fraction_index * axes.tips_m.size() + tip_index);
  }
};

// The mesh size and mode count a setup solves designs with (its own, else the template's).
double solved_mesh_size(const PredictionSetup& setup);
int solved_modes(const PredictionSetup& setup);

// Checks a grid read back or computed against itself: node count, mode counts, |H| lengths, every
// |H| and ω positive and finite. Throws std::invalid_argument naming `where`, the node and what
// was expected.
void validate(const DesignResponseGrid& grid, const std::string& where);

// Counts the mode jumps (above) between every pair of neighbouring nodes.
std::size_t count_mode_jumps(const DesignResponseGrid& grid);

// Solves every node's design (simulate_response), on `threads` threads (0: one per core; Gmsh
// meshes one at a time, assembly and eigensolve run in parallel). A node `known` already holds is
// copied instead: one at exactly the same fraction and tip, in a grid of the same two materials,
// mesh size, mode count and frequencies (a coarse grid's nodes in its fine grid). The grid records
// nothing else of its solve, so `known` must come from this setup's template and materials (as a
// grid cached under these inputs' key does). `progress` is called after each node solved with done
// of total, the nodes to solve (known ones are not counted); `stop` is checked before each node
// starts, and a stop requested throws numeric::Cancelled once the nodes under way have finished
// (at most one node's time per thread). Throws for axes validate refuses, a tip outside the forcing
// model's fitted tips, a `known` grid validate refuses, and what the FEM throws (naming the node's
// design point).
DesignResponseGrid compute_design_response_grid(const PredictionSetup& setup, const GridAxes& axes,
                                                const numeric::Progress& progress = {},
                                                std::stop_token stop = {}, unsigned threads = 0,
                                                const DesignResponseGrid* known = nullptr);

// The response at (λ, tip) inside the grid, interpolated as the header says. Throws
// std::invalid_argument for a point outside the grid (saying by how far and the grid's range).
SimulatedResponse interpolate_response(const DesignResponseGrid& grid, double fraction,
                                       double tip_m);

// The cheap path, once per slider move: predict_from_response with the interpolated
// response. Throws as interpolate_response and predict_from_response do, and when the grid's
// frequencies are not the setup's forcing model's (a grid of another model).
PredictedTool predict_from_grid(const PredictionSetup& setup, const DesignResponseGrid& grid,
                                double fraction, double tip_m, const std::string& surface);

// predict_from_grid as a predictor of design points (design_search.hpp's Predict): the point's
// fraction of the grid's material_b and its tip. Throws std::invalid_argument for a point with a
// material the grid does not mix (naming it), and as predict_from_grid does.
std::function<PredictedTool(const DesignPoint&)> grid_predictor(const PredictionSetup& setup,
                                                                const DesignResponseGrid& grid,
                                                                const std::string& surface);

}  // namespace nibrig::model::design
