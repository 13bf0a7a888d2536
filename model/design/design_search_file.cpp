#include "model/design/design_search_file.hpp"

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"

namespace nibrig::model::design {

nlohmann::json candidate_json(const Candidate& c) {
  return {{"design", to_string(c.point)},
          {"distance", c.distance},
          {"distance_sd", c.distance_sd},
          {"mu", c.mu},
          {"weighted_mean", c.weighted_mean},
          {"coordinates", std::vector<double>(c.placement.mean.data(),
                                              c.placement.mean.data() + c.placement.mean.size())}};
}

nlohmann::json design_search_json(const SearchResult& result,
                                  const DesignSearchDescription& description) {
  nlohmann::json j;
  j["kind"] = "design_search";
  j["target"] = description.target;
  j["surface"] = description.surface;
  j["search"] = description.search;
  j["seconds"] = description.seconds;
  if (!description.space.empty()) j["space"] = description.space;
  j["optimum"] = candidate_json(result.best());
  j["runners_up"] = nlohmann::json::array();
  for (std::size_t k : result.runners_up(description.runners_up))
    j["runners_up"].push_back(candidate_json(result.evaluated[k]));
  j["path"] = nlohmann::json::array();
  for (const auto& c : result.evaluated) j["path"].push_back(candidate_json(c));
  return j;
}

void write_design_search(const std::filesystem::path& file, const SearchResult& result,
                         const DesignSearchDescription& description) {
  io::write_file_atomically(file, io::json_text(design_search_json(result, description), file));
}

}  // namespace nibrig::model::design
