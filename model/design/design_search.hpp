// Stylus design by search in the perceptual space (Sec. 6.2, Fig. 17): the design whose predicted
// tool lies closest to a target tool. Each candidate is a prediction (predicted_tool.hpp) placed
// from its descriptors through the space's descriptor map, with that placement's uncertainty.
//
// Two searches: along the line between two designs (the paper's line search: a scan at equal
// steps, then golden-section refinement inside the best step, since the distance need not be
// unimodal along the line), and over the whole 2-D range of a two-material mix × tip diameter (a
// grid, then two rounds of a finer grid around the best cell). Every candidate evaluated is kept:
// in order they are the path drawn in the space; ranked, the optimum and its runners-up.
#pragma once

#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "model/design/design_constraints.hpp"
#include "model/design/design_point.hpp"
#include "model/design/predicted_tool.hpp"
#include "model/space/descriptor_map.hpp"

namespace nibrig::model::design {

struct Candidate {
  DesignPoint point;
  space::Placement placement;
  double mu = 0.0, weighted_mean = 0.0;  // the predicted descriptors, for reports
  // Distance of the placement's mean to the target's, and its standard deviation when both
  // positions are drawn from their uncertainties (space::uncertain_distance).
  double distance = 0.0, distance_sd = 0.0;
  // Its distance to each target, with its sd: one entry for one target; for a group (below),
  // `distance` is their largest or mean.
  std::vector<double> target_distances, target_distance_sds;
  // What a search minimises when set (a design loop's rule: design_loop.hpp); else `distance`.
  std::optional<double> score;

  double search_key() const { return score.value_or(distance); }
};

// Where a predicted tool lies: its descriptors (those the map was fitted with: μ and the weighted
// vibration, as space::paper_descriptor_names) through the map, its uncertainty the map's
// prediction covariance plus the tool's descriptor error carried through the map
// (descriptor_uncertainty.hpp). Throws what the descriptor code throws for a tool without a usable
// descriptor.
space::Placement place_predicted(const space::DescriptorMap& map, const PredictedTool& tool);
// The descriptors place_predicted places: the map's, in its order.
Eigen::VectorXd predicted_descriptors(const space::DescriptorMap& map, const PredictedTool& tool);

using Evaluate = std::function<Candidate(const DesignPoint&)>;

// Called after each candidate is evaluated (each is an FEM prediction, the slow part), with
// done = 1, 2, ... and a total fixed for the whole search: the most candidates it can evaluate,
// known from its options before the first. The count reaches the total unless the optimum lies at
// the edge of the range, where fewer candidates remain to refine: a face ends its bar when the
// search returns.
using SearchProgress =
    std::function<void(const Candidate& evaluated, std::size_t done, std::size_t total)>;

// The evaluation a search uses: predict, place, measure the distance to `target`.
Evaluate distance_to_target(const PredictionSetup& setup, const std::string& surface,
                            const space::DescriptorMap& map, const space::Placement& target,
                            int samples = 2000, std::uint64_t seed = 1);
// The same with another predictor: a design-response grid's interpolation (grid_predictor in
// design_response_grid.hpp, milliseconds a candidate) where the above solves the FEM (a second).
using Predict = std::function<PredictedTool(const DesignPoint&)>;
Evaluate distance_to_target(Predict predict, const space::DescriptorMap& map,
                            const space::Placement& target, int samples = 2000,
                            std::uint64_t seed = 1);

// The evaluation of a design for a group of tools (Sec. 7: "one nib for all pencils on office
// paper"): its distance is the largest or the mean of its distances to the targets, with the sd of
// that over joint draws (space::uncertain_group_distance); each target's own distance is kept.
Evaluate distance_to_targets(Predict predict, const space::DescriptorMap& map,
                             std::vector<space::Placement> targets, space::GroupAim aim,
                             int samples = 2000, std::uint64_t seed = 1);
Evaluate distance_to_targets(const PredictionSetup& setup, const std::string& surface,
                             const space::DescriptorMap& map, std::vector<space::Placement> targets,
                             space::GroupAim aim, int samples = 2000, std::uint64_t seed = 1);

// Indices into `evaluated`, nearest first by search_key(); equal keys keep their order.
std::vector<std::size_t> ranking(const std::vector<Candidate>& evaluated);

struct SearchResult {
  std::vector<Candidate> evaluated;  // in the order evaluated: the path
  std::vector<std::size_t> ranked;   // indices into evaluated, nearest first

  const Candidate& best() const { return evaluated.at(ranked.at(0)); }
  // Up to `count` candidates after the optimum, in rank order, each a design of its own: one
  // within kSameDesignFraction of mix and kSameDesignTip of tip of a better one listed (the
  // refinement's near neighbours of the optimum) is skipped. Indices into evaluated.
  std::vector<std::size_t> runners_up(std::size_t count) const;
};

// Mixes closer than this (half the summed |Δfraction|) with tips closer than kSameDesignTip are
// one design for a report: a printer dithers in steps of a few per cent.
inline constexpr double kSameDesignFraction = 0.05;
inline constexpr double kSameDesignTip = 0.0001;  // m
bool same_design(const DesignPoint& a, const DesignPoint& b);

struct LineSearchOptions {
  int scan_points = 9;             // equal steps from a to b, both ends included
  double refine_tolerance = 0.01;  // of the line's length, for the golden-section refinement
  DesignConstraints constraints;   // the search keeps to the segment they allow
};

// The point interpolate(a, b, λ) with λ in [0, 1] nearest to the target, among those the
// constraints allow (feasible_segment: the scan and refinement run along that segment; one design
// allowed is the one candidate). Throws std::invalid_argument for fewer than 2 scan points, a
// tolerance outside (0, 1), or constraints that allow nothing on the line (naming them).
SearchResult line_search(const DesignPoint& a, const DesignPoint& b, const Evaluate& evaluate,
                         const LineSearchOptions& options = {},
                         const SearchProgress& progress = {});

struct RangeSearchOptions {
  std::string first_material = "vero", second_material = "DM85";  // mix = second's fraction
  double min_tip_m = 0.001, max_tip_m = 0.004;
  int fraction_points = 5, tip_points = 4;  // the first grid, ends included
  int refinements = 2;                      // finer 3 × 3 grids around the best, halving steps
  DesignConstraints constraints;            // narrow the tips and fractions searched
};

// The mix of the two materials (the second's fraction from 0 to 1) × tip diameter nearest to the
// target, within the constraints: the grid spans the tips and fractions they allow (an axis they
// fix to one value has one point). Throws std::invalid_argument for a grid of fewer than 2 points
// per axis, equal materials, an empty tip range, or constraints that allow nothing (naming them).
SearchResult range_search(const Evaluate& evaluate, const RangeSearchOptions& options = {},
                          const SearchProgress& progress = {});

}  // namespace nibrig::model::design
