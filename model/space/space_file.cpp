#include "model/space/space_file.hpp"

#include <nlohmann/json.hpp>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"

namespace nibrig::model::space {

namespace jf = io::json_fields;

void write_space_file(const std::filesystem::path& file, const SpaceFile& s) {
  nlohmann::json coordinates = nlohmann::json::array();
  for (Eigen::Index i = 0; i < s.coordinates.cols(); ++i) {
    std::vector<double> point(s.coordinates.col(i).data(),
                              s.coordinates.col(i).data() + s.coordinates.rows());
    coordinates.push_back(point);
  }
  const nlohmann::json j = {
      {"format", "nibrig-space"},
      {"version", 1},
      {"model", "P(a closer to reference than b) = Phi(-scale * (|Q_a - Q_ref| - |Q_b - Q_ref|))"},
      {"dims", s.coordinates.rows()},
      {"scale", s.scale},
      {"lambda", s.lambda},
      {"stimuli", s.stimuli},
      {"coordinates", coordinates},
      {"fit",
       {{"objective", s.objective},
        {"negative_log_likelihood", s.negative_log_likelihood},
        {"start_objectives", s.start_objectives},
        {"triplets", s.triplets},
        {"responses", s.responses}}},
      {"provenance", {{"judgments", s.judgments}}}};
  io::write_file_atomically(file, j.dump(2) + "\n");
}

SpaceFile read_space_file(const std::filesystem::path& file) {
  const nlohmann::json root = jf::parse_file(file);
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, "nibrig-space", 1);
  SpaceFile s;
  s.scale = jf::number_member(root, "scale", file, "");
  if (!(s.scale > 0)) throw io::FormatError(file, jf::place("scale"), "expected a positive number");
  s.lambda = root.contains("lambda") ? jf::number_member(root, "lambda", file, "") : 0.0;
  const auto& names = jf::as_array(jf::member(root, "stimuli", file, ""), file, "stimuli");
  for (std::size_t i = 0; i < names.size(); ++i)
    s.stimuli.push_back(jf::as_string(names[i], file, jf::element_path("stimuli", i)));
  const auto& points = jf::as_array(jf::member(root, "coordinates", file, ""), file, "coordinates");
  if (points.size() != s.stimuli.size())
    throw io::FormatError(file, jf::place("coordinates"),
                          "expected one point per stimulus (" + std::to_string(s.stimuli.size()) +
                              "), found " + std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string at = jf::element_path("coordinates", i);
    const auto point = jf::as_number_array(points[i], file, at);
    if (i == 0)
      s.coordinates.resize(static_cast<Eigen::Index>(point.size()),
                           static_cast<Eigen::Index>(points.size()));
    if (point.empty() || static_cast<Eigen::Index>(point.size()) != s.coordinates.rows())
      throw io::FormatError(file, jf::place(at),
                            "expected " + std::to_string(s.coordinates.rows()) + " coordinates");
    for (std::size_t d = 0; d < point.size(); ++d)
      s.coordinates(static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(i)) = point[d];
  }
  if (root.contains("provenance") && root["provenance"].contains("judgments"))
    s.judgments = jf::as_string(root["provenance"]["judgments"], file, "provenance.judgments");
  return s;
}

}  // namespace nibrig::model::space
