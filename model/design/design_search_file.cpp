#include "model/design/design_search_file.hpp"

#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"

namespace nibrig::model::design {

nlohmann::json candidate_json(const Candidate& c, const std::map<std::string, double>& cost) {
  nlohmann::json j{{"design", to_string(c.point)},
                   {"distance", c.distance},
                   {"distance_sd", c.distance_sd},
                   {"mu", c.mu},
                   {"weighted_mean", c.weighted_mean},
                   {"coordinates", std::vector<double>(c.placement.mean.data(),
                                                       c.placement.mean.data() + c.placement.mean.size())},
                   {"target_distances", c.target_distances},
                   {"target_distance_sds", c.target_distance_sds}};
  if (!cost.empty()) j["cost"] = design_cost(c.point, cost);
  return j;
}

namespace {

nlohmann::json constraints_json(const DesignConstraints& c) {
  nlohmann::json j = nlohmann::json::object();
  if (c.min_tip_m) j["min_tip_mm"] = *c.min_tip_m * 1e3;
  if (c.max_tip_m) j["max_tip_mm"] = *c.max_tip_m * 1e3;
  if (!c.materials.empty()) j["materials"] = c.materials;
  if (!c.cost.empty()) j["cost"] = c.cost;
  if (c.max_cost) j["max_cost"] = *c.max_cost;
  return j;
}

}  // namespace

nlohmann::json design_search_json(const SearchResult& result,
                                  const DesignSearchDescription& description) {
  nlohmann::json j;
  j["kind"] = "design_search";
  j["target"] = description.target;
  j["surface"] = description.surface;
  j["search"] = description.search;
  j["seconds"] = description.seconds;
  if (!description.space.empty()) j["space"] = description.space;
  j["placed"] = description.placed;
  if (!description.targets.empty()) j["targets"] = description.targets;
  if (!description.aim.empty()) j["aim"] = description.aim;
  const auto& cost = description.constraints.cost;
  if (description.constraints.any() || !cost.empty()) j["constraints"] = constraints_json(description.constraints);
  j["optimum"] = candidate_json(result.best(), cost);
  j["runners_up"] = nlohmann::json::array();
  for (std::size_t k : result.runners_up(description.runners_up))
    j["runners_up"].push_back(candidate_json(result.evaluated[k], cost));
  j["path"] = nlohmann::json::array();
  for (const auto& c : result.evaluated) j["path"].push_back(candidate_json(c, cost));
  if (const auto& guided = description.guided) {
    if (guided->fem_solved.size() != result.evaluated.size())
      throw std::invalid_argument("design search: a FEM flag per candidate expected");
    j["grid"] = {{"error", guided->grid_error}, {"fem_solves", guided->fem_solves}};
    for (std::size_t k = 0; k < result.evaluated.size(); ++k)
      j["path"][k]["fem_solved"] = static_cast<bool>(guided->fem_solved[k]);
  }
  return j;
}

void write_design_search(const std::filesystem::path& file, const SearchResult& result,
                         const DesignSearchDescription& description) {
  io::write_file_atomically(file, io::json_text(design_search_json(result, description), file));
}

}  // namespace nibrig::model::design
