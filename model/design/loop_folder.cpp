#include "model/design/loop_folder.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"
#include "model/io/format_error.hpp"
#include "model/io/job_files.hpp"
#include "model/io/json_fields.hpp"

namespace nibrig::model::design {

namespace fs = std::filesystem;
namespace fields = io::json_fields;

namespace {

constexpr const char* kLoopFormat = "nibrig-design-loop";
constexpr const char* kRoundFormat = "nibrig-design-loop-round";
constexpr int kLoopFileVersion = 1;

std::vector<double> as_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

Eigen::VectorXd vector_member(const nlohmann::json& object, const std::string& key,
                              const fs::path& file, const std::string& parent) {
  const auto values = fields::as_number_array(fields::member(object, key, file, parent), file,
                                              fields::member_path(parent, key));
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

}  // namespace

void check_loop_request(const LoopRequest& r) {
  if (r.target.empty()) throw std::invalid_argument("a design loop needs a target (tool/surface)");
  if (r.surface.empty())
    throw std::invalid_argument("a design loop needs the surface its stylus is for");
  if (r.space_file.empty())
    throw std::invalid_argument("a design loop needs a space with a descriptor map to place its prints in");
  if (r.max_rounds < 1 || r.max_rounds > kMostLoopRounds)
    throw std::invalid_argument(
        fmt::format("rounds: {}: expected 1 to {}", r.max_rounds, kMostLoopRounds));
  if (r.first_material == r.second_material)
    throw std::invalid_argument("the loop's mix needs two different materials, not " +
                                r.first_material + " twice");
  for (const auto& c : r.candidates) {
    validate(c);
    for (const auto& share : c.mix)
      if (share.fraction > 0 && share.material != r.first_material &&
          share.material != r.second_material)
        throw std::invalid_argument("candidate " + label(c) + ": " + share.material +
                                    " is not in the loop's mix of " + r.first_material + " and " +
                                    r.second_material);
  }
}

fs::path loop_request_file(const fs::path& folder) { return folder / "loop.json"; }
fs::path round_folder(const fs::path& folder, int round) {
  return folder / ("round-" + std::to_string(round));
}
fs::path round_file(const fs::path& folder, int round) {
  return round_folder(folder, round) / "round.json";
}
fs::path round_print_file(const fs::path& folder, int round) {
  return round_folder(folder, round) / "print" / "stylus.3mf";
}
fs::path round_session_folder(const fs::path& folder, int round) {
  return round_folder(folder, round) / "session";
}
fs::path round_measurement_file(const fs::path& folder, int round) {
  return round_folder(folder, round) / "measurement.json";
}
fs::path round_forcing_file(const fs::path& folder, int round) {
  return round_folder(folder, round) / "forcing.json";
}

void write_loop_request(const fs::path& folder, const LoopRequest& r) {
  nlohmann::json j{{"format", kLoopFormat},
                   {"version", kLoopFileVersion},
                   {"target", r.target},
                   {"surface", r.surface},
                   {"space", r.space_file.string()},
                   {"catalog", r.catalog_file.string()},
                   {"forcing", r.forcing},
                   {"printer", r.printer},
                   {"mix", {r.first_material, r.second_material}},
                   {"rule", rule_name(r.rule)},
                   {"max_rounds", r.max_rounds}};
  if (!r.candidates.empty()) {
    nlohmann::json& candidates = j["candidates"] = nlohmann::json::array();
    for (const auto& c : r.candidates) candidates.push_back(to_string(c));
  }
  fs::create_directories(folder);
  // A resumed loop given a new round limit read the request it now rewrites, on purpose.
  io::release_input(loop_request_file(folder));
  io::write_file_atomically(loop_request_file(folder), io::json_text(j, loop_request_file(folder)));
}

LoopRequest read_loop_request(const fs::path& folder) {
  const fs::path file = loop_request_file(folder);
  const nlohmann::json j = fields::parse_file(file);
  fields::check_format_and_version(j, file, kLoopFormat, kLoopFileVersion);
  LoopRequest r;
  r.target = fields::string_member(j, "target", file, "");
  r.surface = fields::string_member(j, "surface", file, "");
  r.space_file = fields::string_member(j, "space", file, "");
  r.catalog_file = fields::string_member(j, "catalog", file, "");
  r.forcing = fields::string_member(j, "forcing", file, "");
  r.printer = fields::string_member(j, "printer", file, "");
  const auto& mix = fields::as_array(fields::member(j, "mix", file, ""), file, "mix");
  if (mix.size() != 2) throw io::FormatError(file, fields::place("mix"), "two materials expected");
  r.first_material = fields::as_string(mix[0], file, "mix[0]");
  r.second_material = fields::as_string(mix[1], file, "mix[1]");
  try {
    r.rule = parse_next_print_rule(fields::string_member(j, "rule", file, ""));
  } catch (const std::invalid_argument& e) {
    throw io::FormatError(file, fields::place("rule"), e.what());
  }
  r.max_rounds = static_cast<int>(fields::as_integer(fields::member(j, "max_rounds", file, ""),
                                                     file, "max_rounds", 1, kMostLoopRounds));
  if (j.contains("candidates")) {
    const auto& candidates = fields::as_array(j.at("candidates"), file, "candidates");
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const std::string where = fields::element_path("candidates", i);
      try {
        r.candidates.push_back(parse_design_point(fields::as_string(candidates[i], file, where)));
      } catch (const std::invalid_argument& e) {
        throw io::FormatError(file, fields::place(where), e.what());
      }
    }
  }
  return r;
}

void write_round(const fs::path& folder, const LoopRoundRecord& r) {
  nlohmann::json j{{"format", kRoundFormat},
                   {"version", kLoopFileVersion},
                   {"round", r.number},
                   {"design", to_string(r.design)},
                   {"predicted",
                    {{"distance", r.predicted_distance},
                     {"distance_sd", r.predicted_distance_sd},
                     {"chance_within_threshold", r.chance_within},
                     {"position", as_vector(r.predicted_position)}}}};
  if (r.measured)
    j["measured"] = {{"distance", r.measured->distance},
                     {"distance_sd", r.measured->distance_sd},
                     {"position", as_vector(r.measured->position)},
                     {"descriptors", as_vector(r.measured->descriptors)}};
  if (!r.stopped.empty()) j["stopped"] = r.stopped;
  fs::create_directories(round_folder(folder, r.number));
  // A resumed loop read the record it now completes: replacing it is the point.
  io::release_input(round_file(folder, r.number));
  io::write_file_atomically(round_file(folder, r.number),
                            io::json_text(j, round_file(folder, r.number)));
}

std::vector<LoopRoundRecord> read_rounds(const fs::path& folder) {
  std::vector<LoopRoundRecord> rounds;
  for (int n = 1; fs::exists(round_file(folder, n)); ++n) {
    const fs::path file = round_file(folder, n);
    const nlohmann::json j = fields::parse_file(file);
    fields::check_format_and_version(j, file, kRoundFormat, kLoopFileVersion);
    LoopRoundRecord r;
    r.number = static_cast<int>(
        fields::as_integer(fields::member(j, "round", file, ""), file, "round", n, n));
    try {
      r.design = parse_design_point(fields::string_member(j, "design", file, ""));
    } catch (const std::invalid_argument& e) {
      throw io::FormatError(file, fields::place("design"), e.what());
    }
    const auto& predicted =
        fields::as_object(fields::member(j, "predicted", file, ""), file, "predicted");
    r.predicted_distance = fields::number_member(predicted, "distance", file, "predicted");
    r.predicted_distance_sd = fields::number_member(predicted, "distance_sd", file, "predicted");
    r.chance_within =
        fields::number_member(predicted, "chance_within_threshold", file, "predicted");
    r.predicted_position = vector_member(predicted, "position", file, "predicted");
    if (j.contains("measured")) {
      const auto& m = fields::as_object(j["measured"], file, "measured");
      LoopMeasuredRecord measured;
      measured.distance = fields::number_member(m, "distance", file, "measured");
      measured.distance_sd = fields::number_member(m, "distance_sd", file, "measured");
      measured.position = vector_member(m, "position", file, "measured");
      measured.descriptors = vector_member(m, "descriptors", file, "measured");
      r.measured = measured;
    }
    if (j.contains("stopped")) r.stopped = fields::as_string(j["stopped"], file, "stopped");
    rounds.push_back(std::move(r));
  }
  return rounds;
}

}  // namespace nibrig::model::design
