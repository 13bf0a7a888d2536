// The design search's report (`nibrig design -o`, FORMATS.md "Design search"): the optimum, the
// runners-up and every candidate in the order evaluated, each with its design, distance to the
// target, predicted descriptors and place in the space.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "model/design/design_search.hpp"

namespace nibrig::model::design {

// A search through a design grid (grid_guided_search.hpp): which candidates the FEM solved, the
// grid's error measured and the FEM solves made.
struct GuidedDescription {
  std::vector<bool> fem_solved;  // per candidate of the path
  double grid_error = 0.0;
  std::size_t fem_solves = 0;
};

// What the search was: its target and surface, how it searched (in words), how long it took and
// how many runners-up to report; the space file it searched in, empty when not named.
// A group design names every target and its aim ("largest" or "mean" distance); `target` is then
// their names joined. The constraints are written when any is set.
struct DesignSearchDescription {
  std::string target, surface, search;
  double seconds = 0.0;
  std::size_t runners_up = 4;
  std::string space;
  std::vector<std::string> targets;
  std::string aim;
  DesignConstraints constraints;
  // The targets placed from their descriptors (a catalog pairing the space never judged); the
  // others are the space's own stimuli.
  std::vector<std::string> placed;
  std::optional<GuidedDescription> guided;
};

// One candidate: design, distance, distance_sd, mu, weighted_mean, coordinates, and
// target_distances / target_distance_sds (one per target, in the description's order); with
// costs given, its cost.
nlohmann::json candidate_json(const Candidate& candidate, const std::map<std::string, double>& cost = {});

// kind "design_search": target, surface, search, seconds, space (when named), placed, targets and
// aim (a group), constraints {min_tip_mm, max_tip_mm, materials, cost, max_cost} (when any),
// optimum, runners_up (distinct designs, SearchResult::runners_up), path (every candidate in the
// order evaluated); through a grid, grid {error, fem_solves} and each path candidate's fem_solved.
nlohmann::json design_search_json(const SearchResult& result,
                                  const DesignSearchDescription& description);

// Written atomically; throws io::UnwritableOutput naming a field that is not finite,
// std::runtime_error naming the file when it cannot be written.
void write_design_search(const std::filesystem::path& file, const SearchResult& result,
                         const DesignSearchDescription& description);

}  // namespace nibrig::model::design
