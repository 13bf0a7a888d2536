#include "model/space/space_file.hpp"

#include <nlohmann/json.hpp>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/space/objective.hpp"
#include "model/io/finite_output.hpp"

namespace nibrig::model::space {

namespace jf = io::json_fields;

namespace {

nlohmann::json rows_of(const Eigen::MatrixXd& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    std::vector<double> row(static_cast<std::size_t>(m.cols()));
    for (Eigen::Index c = 0; c < m.cols(); ++c) row[static_cast<std::size_t>(c)] = m(r, c);
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json vector_of(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

// A rows × cols matrix stored as an array of rows at `path`.
Eigen::MatrixXd matrix_at(const nlohmann::json& value, const std::filesystem::path& file,
                          const std::string& path, Eigen::Index rows, Eigen::Index cols) {
  const auto& array = jf::as_array(value, file, path);
  if (static_cast<Eigen::Index>(array.size()) != rows)
    throw io::FormatError(file, jf::place(path),
                          "expected " + std::to_string(rows) + " rows, found " +
                              std::to_string(array.size()));
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const std::string at = jf::element_path(path, static_cast<std::size_t>(r));
    const auto row = jf::as_number_array(array[static_cast<std::size_t>(r)], file, at);
    if (static_cast<Eigen::Index>(row.size()) != cols)
      throw io::FormatError(file, jf::place(at), "expected " + std::to_string(cols) + " values");
    for (Eigen::Index c = 0; c < cols; ++c) m(r, c) = row[static_cast<std::size_t>(c)];
  }
  return m;
}

Eigen::VectorXd vector_at(const nlohmann::json& value, const std::filesystem::path& file,
                          const std::string& path, Eigen::Index size) {
  const auto v = jf::as_number_array(value, file, path);
  if (static_cast<Eigen::Index>(v.size()) != size)
    throw io::FormatError(file, jf::place(path), "expected " + std::to_string(size) + " values");
  return Eigen::Map<const Eigen::VectorXd>(v.data(), size);
}

// The model in words, for a reader of the file.
std::string model_formula(const ModelFamily& f) {
  std::string p;
  switch (f.link) {
    case Link::probit: p = "Phi(scale * (|Q_b - Q_ref| - |Q_a - Q_ref|) / sigma)"; break;
    case Link::logistic: p = "1 / (1 + exp(-1.702 * scale * (|Q_b - Q_ref| - |Q_a - Q_ref|) / sigma))"; break;
    case Link::student_t:
      p = "K(a) / (K(a) + K(b)), K(x) = (1 + (scale * |Q_x - Q_ref| / sigma)^2 / alpha)^(-(alpha + 1) / 2), "
          "alpha = max(1, dims - 1)";
      break;
  }
  std::string text = "P(a closer to reference than b) = ";
  text += f.lapse ? "lapse / 2 + (1 - lapse) * " + p : p;
  text += f.stimulus_noise ? "; sigma = sqrt(mean of exp(2 * log_noise) over the three stimuli)" : "; sigma = 1";
  return text;
}

nlohmann::json judgment_model_json(const SpaceFile& s) {
  nlohmann::json j = {{"family", family_name(s.model.family)}, {"lapse", s.model.lapse}};
  if (s.model.log_noise.size() > 0) j["log_noise"] = vector_of(s.model.log_noise);
  if (!s.model_reason.empty()) j["chosen_because"] = s.model_reason;
  if (!s.model_scores.empty()) {
    nlohmann::json scores = nlohmann::json::array();
    for (const auto& m : s.model_scores)
      scores.push_back({{"family", m.family},
                        {"log_loss", m.log_loss},
                        {"majority_agreement", m.majority_agreement},
                        {"individual_agreement", m.individual_agreement},
                        {"mean_error", m.mean_error}});
    j["cross_validation"] = scores;
  }
  return j;
}

// "judgment_model" (a file before it existed holds the paper's model: probit, no lapse, no noises).
void read_judgment_model(const nlohmann::json& root, const std::filesystem::path& file, SpaceFile& s) {
  if (!root.contains("judgment_model")) return;
  const std::string at = "judgment_model";
  const auto& j = jf::as_object(root[at], file, at);
  const std::string family = jf::as_string(jf::member(j, "family", file, at), file, jf::member_path(at, "family"));
  try {
    s.model.family = parse_family(family);
  } catch (const std::invalid_argument& e) {
    throw io::FormatError(file, jf::place(jf::member_path(at, "family")), e.what());
  }
  s.model.lapse = jf::number_member(j, "lapse", file, at);
  if (!(s.model.lapse >= 0 && s.model.lapse < 0.5) || (!s.model.family.lapse && s.model.lapse != 0))
    throw io::FormatError(file, jf::place(jf::member_path(at, "lapse")),
                          "expected a share in [0, 0.5), and 0 for a family without a lapse");
  if (s.model.family.stimulus_noise) {
    s.model.log_noise = vector_at(jf::member(j, "log_noise", file, at), file, jf::member_path(at, "log_noise"),
                                  s.coordinates.cols());
    if (!s.model.log_noise.allFinite())
      throw io::FormatError(file, jf::place(jf::member_path(at, "log_noise")), "expected finite numbers");
  }
  if (j.contains("chosen_because"))
    s.model_reason = jf::as_string(j["chosen_because"], file, jf::member_path(at, "chosen_because"));
  if (j.contains("cross_validation")) {
    const std::string cv = jf::member_path(at, "cross_validation");
    const auto& scores = jf::as_array(j["cross_validation"], file, cv);
    for (std::size_t i = 0; i < scores.size(); ++i) {
      const std::string e = jf::element_path(cv, i);
      ModelScore m;
      m.family = jf::as_string(jf::member(scores[i], "family", file, e), file, jf::member_path(e, "family"));
      m.log_loss = jf::number_member(scores[i], "log_loss", file, e);
      m.majority_agreement = jf::number_member(scores[i], "majority_agreement", file, e);
      m.individual_agreement = jf::number_member(scores[i], "individual_agreement", file, e);
      m.mean_error = jf::number_member(scores[i], "mean_error", file, e);
      s.model_scores.push_back(m);
    }
  }
}

nlohmann::json map_json(const DescriptorMap& m) {
  return {{"descriptor_mean", vector_of(m.descriptor_mean)},
          {"descriptor_scale", vector_of(m.descriptor_scale)},
          {"coefficients", rows_of(m.coefficients)},
          {"design_inverse", rows_of(m.design_inverse)},
          {"residual_covariance", rows_of(m.residual_covariance)},
          {"r_squared", m.r_squared},
          {"samples", m.samples}};
}

DescriptorMap read_map(const nlohmann::json& j, const std::filesystem::path& file,
                       const std::vector<std::string>& names, Eigen::Index dims) {
  const std::string at = "descriptor_map";
  jf::as_object(j, file, at);
  const auto p = static_cast<Eigen::Index>(names.size());
  DescriptorMap m;
  m.descriptor_names = names;
  auto field = [&](const char* key) { return jf::member_path(at, key); };
  m.descriptor_mean = vector_at(jf::member(j, "descriptor_mean", file, at), file,
                                field("descriptor_mean"), p);
  m.descriptor_scale = vector_at(jf::member(j, "descriptor_scale", file, at), file,
                                 field("descriptor_scale"), p);
  m.coefficients = matrix_at(jf::member(j, "coefficients", file, at), file, field("coefficients"),
                             dims, p + 1);
  m.design_inverse = matrix_at(jf::member(j, "design_inverse", file, at), file,
                               field("design_inverse"), p + 1, p + 1);
  m.residual_covariance = matrix_at(jf::member(j, "residual_covariance", file, at), file,
                                    field("residual_covariance"), dims, dims);
  const auto r2 = jf::as_number_array(jf::member(j, "r_squared", file, at), file, field("r_squared"));
  m.r_squared = r2;
  m.samples = static_cast<std::size_t>(
      jf::as_integer(jf::member(j, "samples", file, at), file, field("samples"), 0, 1LL << 40));
  return m;
}

}  // namespace

std::string space_file_text(const SpaceFile& s, const std::filesystem::path& file) {
  nlohmann::json coordinates = nlohmann::json::array();
  for (Eigen::Index i = 0; i < s.coordinates.cols(); ++i) {
    std::vector<double> point(s.coordinates.col(i).data(),
                              s.coordinates.col(i).data() + s.coordinates.rows());
    coordinates.push_back(point);
  }
  const nlohmann::json j = {
      {"format", "nibrig-space"},
      {"version", 1},
      {"model", model_formula(s.model.family)},
      {"dims", s.coordinates.rows()},
      {"scale", s.model.scale},
      {"judgment_model", judgment_model_json(s)},
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
  nlohmann::json out = j;
  out["fit"]["seconds"] = s.seconds;
  if (!s.descriptor_names.empty()) {
    out["descriptors"] = {{"names", s.descriptor_names},
                          {"values", rows_of(s.descriptors)},
                          {"source", s.descriptor_source}};
    out["provenance"]["descriptors"] = s.descriptor_source;
  }
  if (s.descriptor_map) out["descriptor_map"] = map_json(*s.descriptor_map);
  if (!s.regions.empty()) {
    nlohmann::json regions = nlohmann::json::array();
    for (const auto& r : s.regions)
      regions.push_back({{"mean", vector_of(r.mean)},
                         {"covariance", rows_of(r.covariance)},
                         {"radius", r.radius}});
    out["bootstrap"] = {{"resamples", s.bootstrap_resamples},
                        {"levels", s.region_levels},
                        {"regions", regions}};
  }
  return io::json_text(out, file);
}

void write_space_file(const std::filesystem::path& file, const SpaceFile& s) {
  io::write_file_atomically(file, space_file_text(s, file));
}

namespace {
SpaceFile space_from_json(const nlohmann::json& root, const std::filesystem::path& file);
}  // namespace

SpaceFile read_space_file(const std::filesystem::path& file) {
  return space_from_json(jf::parse_file(file), file);
}

SpaceFile parse_space_file(const std::string& text, const std::filesystem::path& file) {
  return space_from_json(jf::parse_text(text, file), file);
}

namespace {
SpaceFile space_from_json(const nlohmann::json& root, const std::filesystem::path& file) {
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, "nibrig-space", 1);
  SpaceFile s;
  s.model.scale = jf::number_member(root, "scale", file, "");
  if (!(s.model.scale > 0)) throw io::FormatError(file, jf::place("scale"), "expected a positive number");
  s.lambda = root.contains("lambda") ? jf::as_number_in(root["lambda"], file, "lambda", 0.0,
                                                        kMaxLambda, "the descriptor weight")
                                     : 0.0;
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
    const auto point =
        jf::as_number_array_in(points[i], file, at, -kMaxCoordinate, kMaxCoordinate,
                               "a coordinate of a perceptual space: fitted ones span a few units");
    if (i == 0)
      s.coordinates.resize(static_cast<Eigen::Index>(point.size()),
                           static_cast<Eigen::Index>(points.size()));
    if (point.empty() || static_cast<Eigen::Index>(point.size()) != s.coordinates.rows())
      throw io::FormatError(file, jf::place(at),
                            "expected " + std::to_string(s.coordinates.rows()) + " coordinates");
    for (std::size_t d = 0; d < point.size(); ++d)
      s.coordinates(static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(i)) = point[d];
  }
  if (root.contains("dims")) {
    const long long dims = jf::as_integer(root["dims"], file, "dims", 1, kMaxSpaceDims);
    if (dims != s.coordinates.rows())
      throw io::FormatError(file, jf::place("dims"),
                            "found " + std::to_string(dims) + ", but each point has " +
                                std::to_string(s.coordinates.rows()) + " coordinates");
  }
  read_judgment_model(root, file, s);
  if (root.contains("provenance") && root["provenance"].contains("judgments"))
    s.judgments = jf::as_string(root["provenance"]["judgments"], file, "provenance.judgments");
  const Eigen::Index dims = s.coordinates.rows(), n = s.coordinates.cols();
  if (root.contains("descriptors")) {
    const auto& d = jf::as_object(root["descriptors"], file, "descriptors");
    const auto& names = jf::as_array(jf::member(d, "names", file, "descriptors"), file,
                                     "descriptors.names");
    for (std::size_t i = 0; i < names.size(); ++i)
      s.descriptor_names.push_back(
          jf::as_string(names[i], file, jf::element_path("descriptors.names", i)));
    s.descriptors = matrix_at(jf::member(d, "values", file, "descriptors"), file,
                              "descriptors.values", n,
                              static_cast<Eigen::Index>(s.descriptor_names.size()));
    if (d.contains("source")) s.descriptor_source = jf::as_string(d["source"], file, "descriptors.source");
  }
  if (root.contains("descriptor_map")) {
    if (s.descriptor_names.empty())
      throw io::FormatError(file, jf::place("descriptor_map"),
                            "a descriptor map needs the descriptors' names (field 'descriptors')");
    s.descriptor_map = read_map(root["descriptor_map"], file, s.descriptor_names, dims);
  }
  if (root.contains("bootstrap")) {
    const auto& b = jf::as_object(root["bootstrap"], file, "bootstrap");
    s.bootstrap_resamples = static_cast<int>(jf::as_integer(
        jf::member(b, "resamples", file, "bootstrap"), file, "bootstrap.resamples", 2, 1 << 30));
    s.region_levels =
        jf::as_number_array(jf::member(b, "levels", file, "bootstrap"), file, "bootstrap.levels");
    const auto& regions =
        jf::as_array(jf::member(b, "regions", file, "bootstrap"), file, "bootstrap.regions");
    if (static_cast<Eigen::Index>(regions.size()) != n)
      throw io::FormatError(file, jf::place("bootstrap.regions"),
                            "expected one region per stimulus (" + std::to_string(n) + ")");
    for (std::size_t i = 0; i < regions.size(); ++i) {
      const std::string at = jf::element_path("bootstrap.regions", i);
      ConfidenceRegion r;
      r.mean = vector_at(jf::member(regions[i], "mean", file, at), file,
                         jf::member_path(at, "mean"), dims);
      r.covariance = matrix_at(jf::member(regions[i], "covariance", file, at), file,
                               jf::member_path(at, "covariance"), dims, dims);
      r.radius = jf::as_number_array(jf::member(regions[i], "radius", file, at), file,
                                     jf::member_path(at, "radius"));
      if (r.radius.size() != s.region_levels.size())
        throw io::FormatError(file, jf::place(jf::member_path(at, "radius")),
                              "expected one radius per level (" +
                                  std::to_string(s.region_levels.size()) + ")");
      s.regions.push_back(r);
    }
  }
  return s;
}

}  // namespace

}  // namespace nibrig::model::space
