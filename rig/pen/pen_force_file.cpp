#include "rig/pen/pen_force_file.hpp"

#include <nlohmann/json.hpp>

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/user_store.hpp"
#include "model/io/utc_time.hpp"

namespace nibrig::rig::pen {
namespace {

namespace jf = model::io::json_fields;
using model::io::FormatError;
using nlohmann::json;

constexpr const char* kPenFileFormat = "nibrig-pen";
constexpr long long kPenFileVersion = 1;

double pen_file_number_in(const json& object, const std::string& key,
                          const std::filesystem::path& file, const std::string& parent, double low,
                          double high, const std::string& why) {
  return jf::as_number_in(jf::member(object, key, file, parent), file, jf::member_path(parent, key),
                          low, high, why);
}

std::vector<PressurePoint> read_pen_points(const json& root, const std::filesystem::path& file) {
  const json& list = jf::as_array(jf::member(root, "points", file, ""), file, "points");
  std::vector<PressurePoint> points;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = jf::element_path("points", i);
    const json& entry = jf::as_object(list[i], file, path);
    PressurePoint p;
    p.pressure = pen_file_number_in(entry, "pressure", file, path, 0.0, 1.0,
                                    "libinput's normalised pressure");
    p.force_n = pen_file_number_in(entry, "force_n", file, path, 0.0, kMaxPenForceN,
                                   "a force on a pen's tip");
    points.push_back(p);
  }
  std::size_t index = 0;
  const std::string problem = pressure_points_problem(points, index);
  if (!problem.empty())
    throw FormatError(
        file, jf::place(points.size() < 2 ? "points" : jf::element_path("points", index)), problem);
  return points;
}

std::vector<PenHold> read_pen_holds(const json& root, const std::filesystem::path& file) {
  const json& list = jf::as_array(jf::member(root, "holds", file, ""), file, "holds");
  std::vector<PenHold> holds;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = jf::element_path("holds", i);
    const json& entry = jf::as_object(list[i], file, path);
    PenHold h;
    h.force_n = pen_file_number_in(entry, "force_n", file, path, 0.0, kMaxPenForceN,
                                   "a force on a pen's tip");
    h.pressure = pen_file_number_in(entry, "pressure", file, path, 0.0, 1.0,
                                    "libinput's normalised pressure");
    h.pressure_sd = pen_file_number_in(entry, "pressure_sd", file, path, 0.0, 1.0,
                                       "a spread of normalised pressures");
    h.samples = static_cast<std::size_t>(jf::as_integer(jf::member(entry, "samples", file, path),
                                                        file, jf::member_path(path, "samples"), 1,
                                                        1'000'000'000));
    holds.push_back(h);
  }
  return holds;
}

}  // namespace

void write_pen_file(const std::filesystem::path& file, const PenCalibration& c) {
  json points = json::array();
  for (const PressurePoint& p : c.curve.points())
    points.push_back({{"pressure", p.pressure}, {"force_n", p.force_n}});
  json holds = json::array();
  for (const PenHold& h : c.holds)
    holds.push_back({{"force_n", h.force_n},
                     {"pressure", h.pressure},
                     {"pressure_sd", h.pressure_sd},
                     {"samples", h.samples}});
  const json j = {{"format", kPenFileFormat},
                  {"version", kPenFileVersion},
                  {"name", c.name},
                  {"created", c.created.empty() ? model::io::now_utc_iso8601() : c.created},
                  {"method", c.method},
                  {"points", points},
                  {"holds", holds}};
  model::io::write_file_atomically(file, model::io::json_text(j, file));
}

PenCalibration read_pen_file(const std::filesystem::path& file) {
  const json root = jf::parse_file(file);
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, kPenFileFormat, kPenFileVersion);
  PenCalibration c;
  c.name = jf::string_member(root, "name", file, "");
  c.created = jf::string_member(root, "created", file, "");
  if (!model::io::is_utc_iso8601(c.created))
    throw FormatError(
        file, jf::place("created"),
        "expected a UTC time as \"2026-01-31T14:05:00Z\", found " + json(c.created).dump());
  c.method = jf::string_member(root, "method", file, "");
  c.curve = PressureCurve(read_pen_points(root, file));
  c.holds = read_pen_holds(root, file);
  return c;
}

std::filesystem::path pen_folder() { return model::io::user_store_folder("NIBRIG_PENS", "pens"); }

std::filesystem::path pen_curve_path(const std::string& name) {
  return model::io::user_store_file(pen_folder(), name, "pen");
}

PenCurveChoice pen_curve_for(const std::string& name) {
  PenCurveChoice choice;
  const std::filesystem::path file = pen_curve_path(name);
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return choice;
  choice.curve = read_pen_file(file).curve;
  choice.is_default = false;
  choice.file = file;
  return choice;
}

}  // namespace nibrig::rig::pen
