// How a rig's RigSession and Comparison pickle: as their records and samples, bit for bit.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/io/json_fields.hpp"
#include "model/io/rig_session_json.hpp"
#include "ui/python/pickle_state.hpp"
#include "ui/python/rig_types.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;

namespace {

constexpr const char* kPickledSession = "a pickled nibrig.rig.RigSession";

constexpr const char* kComparison = "Comparison";

py::tuple comparison_bin_state(const model::io::ComparisonBin& b) {
  return py::make_tuple(b.min_speed_m_s, b.max_speed_m_s, b.mean_speed_m_s, b.rows, b.lsd_db,
                        b.measured_weighted_mean, b.simulated_weighted_mean,
                        b.weighted_mean_log10_difference);
}

model::io::ComparisonBin comparison_bin_of(const py::handle& state) {
  const auto t = state.cast<py::tuple>();
  require_state(t, 8, kComparison);
  const auto number = [&](std::size_t i) { return t[i].cast<double>(); };
  return {number(0), number(1), number(2), t[3].cast<std::uint64_t>(),
          number(4), number(5), number(6), number(7)};
}

// comparison.json's record as its numbers, bit for bit (the file stores speeds in mm/s).
py::tuple report_state(const model::io::ComparisonFile& c) {
  py::list bins;
  for (const auto& b : c.bins) bins.append(comparison_bin_state(b));
  py::object actuator = py::none();
  if (c.actuator)
    actuator = py::make_tuple(c.actuator->contacts, c.actuator->follow_mean_s,
                              c.actuator->follow_max_s, c.actuator->period_s);
  return py::make_tuple(py::make_tuple(c.tool, c.surface, c.sample_rate_hz, c.segment_length, c.hop,
                                       c.window, c.band_min_hz, c.band_max_hz),
                        bins,
                        py::make_tuple(c.bins_with_rows, c.rows, c.rows_outside_speed_range,
                                       c.mean_lsd_db, c.mean_weighted_mean_log10_difference,
                                       c.rows_analysed, c.rows_without_speed, c.blocks_dropped),
                        actuator);
}

model::io::ComparisonFile report_of(const py::handle& state) {
  const auto t = state.cast<py::tuple>();
  require_state(t, 4, kComparison);
  const auto head = t[0].cast<py::tuple>();
  const auto overall = t[2].cast<py::tuple>();
  require_state(head, 8, kComparison);
  require_state(overall, 8, kComparison);
  model::io::ComparisonFile c;
  c.tool = head[0].cast<std::string>(), c.surface = head[1].cast<std::string>();
  c.sample_rate_hz = head[2].cast<double>();
  c.segment_length = head[3].cast<std::uint64_t>(), c.hop = head[4].cast<std::uint64_t>();
  c.window = head[5].cast<std::string>();
  c.band_min_hz = head[6].cast<double>(), c.band_max_hz = head[7].cast<double>();
  for (const auto& b : t[1].cast<py::list>()) c.bins.push_back(comparison_bin_of(b));
  c.bins_with_rows = overall[0].cast<std::uint64_t>(), c.rows = overall[1].cast<std::uint64_t>();
  c.rows_outside_speed_range = overall[2].cast<std::uint64_t>();
  c.mean_lsd_db = overall[3].cast<double>();
  c.mean_weighted_mean_log10_difference = overall[4].cast<double>();
  c.rows_analysed = overall[5].cast<std::uint64_t>();
  c.rows_without_speed = overall[6].cast<std::uint64_t>();
  c.blocks_dropped = overall[7].cast<std::uint64_t>();
  if (!t[3].is_none()) {
    const auto a = t[3].cast<py::tuple>();
    require_state(a, 4, kComparison);
    c.actuator = model::io::ComparisonActuator{a[0].cast<std::uint64_t>(), a[1].cast<double>(),
                                               a[2].cast<double>(), a[3].cast<double>()};
  }
  return c;
}

py::tuple rows_state(const rig::WaterfallRows& r) {
  return py::make_tuple(r.first_row, r.bins, float_bytes(r.measured_db),
                        float_bytes(r.simulated_db), r.times_s, r.speeds_m_s, r.rows_lost);
}

rig::WaterfallRows rows_of(const py::handle& state) {
  const auto t = state.cast<py::tuple>();
  require_state(t, 7, kComparison);
  rig::WaterfallRows r;
  r.first_row = t[0].cast<std::uint64_t>();
  r.bins = t[1].cast<std::size_t>();
  r.measured_db = floats_of(t[2], kComparison);
  r.simulated_db = floats_of(t[3], kComparison);
  r.times_s = t[4].cast<std::vector<double>>();
  r.speeds_m_s = t[5].cast<std::vector<double>>();
  r.rows_lost = t[6].cast<std::uint64_t>();
  if (r.measured_db.size() != r.rows() * r.bins || r.simulated_db.size() != r.measured_db.size())
    throw std::invalid_argument(std::string(kComparison) + ": not a pickled " + kComparison);
  return r;
}

}  // namespace

// A session pickles as what its folder holds, read: session.json's text and the streams' samples.
py::tuple session_state(const Session& s) {
  const auto& r = s.session;
  return py::make_tuple(model::io::session_json::to_json(r.info, nullptr).dump(),
                        float_bytes(r.acceleration), float_bytes(r.speed_m_s),
                        float_bytes(r.normal_force_N), float_bytes(r.tangential_force_N),
                        r.complete, r.folder, r.warnings);
}

Session session_of(const py::tuple& state) {
  require_state(state, 8, "RigSession");
  Session s;
  auto& r = s.session;
  r.info = model::io::session_json::from_json(
               model::io::json_fields::parse_text(state[0].cast<std::string>(), kPickledSession),
               kPickledSession)
               .info;
  r.acceleration = floats_of(state[1], "RigSession");
  r.speed_m_s = floats_of(state[2], "RigSession");
  r.normal_force_N = floats_of(state[3], "RigSession");
  r.tangential_force_N = floats_of(state[4], "RigSession");
  r.complete = state[5].cast<bool>();
  r.folder = state[6].cast<std::filesystem::path>();
  r.warnings = state[7].cast<std::vector<std::string>>();
  return s;
}

py::tuple comparison_state(const Comparison& c) {
  return py::make_tuple(report_state(c.report), c.simulated, c.simulated_modes, c.frequencies_hz,
                        c.measured_mean, c.simulated_mean, rows_state(c.rows),
                        session_state(c.session));
}

Comparison comparison_from(const py::tuple& state) {
  require_state(state, 8, kComparison);
  Comparison c;
  c.report = report_of(state[0]);
  c.simulated = state[1].cast<std::string>();
  c.simulated_modes = state[2].cast<std::string>();
  c.frequencies_hz = state[3].cast<std::vector<double>>();
  c.measured_mean = state[4].cast<std::vector<std::vector<double>>>();
  c.simulated_mean = state[5].cast<std::vector<std::vector<double>>>();
  c.rows = rows_of(state[6]);
  c.session = session_of(state[7].cast<py::tuple>());
  return c;
}

}  // namespace nibrig::ui::python
