// nibrig.rig's results: a session's streams as numpy arrays (read-only views where the library
// holds them as arrays) with what the session says about them, and a comparison's per-speed table
// and waterfall, as `nibrig rig compare` writes them to comparison.json.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "ui/python/errors.hpp"
#include "ui/python/numpy_views.hpp"
#include "ui/python/python_log.hpp"
#include "ui/python/rig_types.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;

namespace {

py::object capture_record(const model::io::RigSessionInfo& info) {
  if (!info.capture) return py::none();
  const auto& c = *info.capture;
  py::dict d;
  d["rig"] = c.rig, d["seconds"] = c.seconds, d["frames"] = c.frames, d["dropped_frames"] = c.dropped_frames;
  d["saturated_frames"] = c.saturated_frames, d["fault_frames"] = c.fault_frames;
  d["alignment_error_ms"] = c.alignment_error_ms, d["ended_because"] = c.ended_because;
  return d;
}

const model::io::RigSession& of(const py::object& self) { return self.cast<const Session&>().session; }

// A per-bin value of the table as an array over the speed bins (a copy: the bins are records).
template <typename T>
py::array_t<T> per_bin(const Comparison& c, T model::io::ComparisonBin::*field) {
  py::array_t<T> a(static_cast<py::ssize_t>(c.report.bins.size()));
  auto out = a.template mutable_unchecked<1>();
  for (std::size_t b = 0; b < c.report.bins.size(); ++b) out(static_cast<py::ssize_t>(b)) = c.report.bins[b].*field;
  return a;
}

// Each bin's mean spectrum of one stream, bins × frequencies, m/s² (a copy).
py::array_t<double> mean_spectra(const Comparison& c, bool simulated) {
  const auto& bins = simulated ? c.simulated_mean : c.measured_mean;
  const std::size_t n = c.frequencies_hz.size();
  py::array_t<double> a({bins.size(), n});
  auto out = a.mutable_unchecked<2>();
  for (std::size_t b = 0; b < bins.size(); ++b) {
    const auto& row = bins[b];
    for (std::size_t f = 0; f < n; ++f)
      out(static_cast<py::ssize_t>(b), static_cast<py::ssize_t>(f)) = f < row.size() ? row[f] : std::nan("");
  }
  return a;
}

// The waterfall's rows × frequency bins in dB, a read-only view of the run's rows.
py::object waterfall_db(const py::object& self, bool simulated) {
  const auto& rows = self.cast<const Comparison&>().rows;
  const auto& v = simulated ? rows.simulated_db : rows.measured_db;
  return array_view(v.data(), v.size(), self).attr("reshape")(rows.rows(), rows.bins);
}

}  // namespace

Comparison comparison_of(rig::ComparisonRun run, model::io::ComparisonFile report,
                         std::string simulated_modes) {
  Comparison c;
  c.report = std::move(report);
  c.simulated = std::move(run.simulated);
  c.simulated_modes = std::move(simulated_modes);
  c.frequencies_hz = std::move(run.table.frequencies_hz);
  for (auto& b : run.table.bins) {
    c.measured_mean.push_back(std::move(b.measured_mean));
    c.simulated_mean.push_back(std::move(b.simulated_mean));
  }
  c.rows = std::move(run.rows);
  return c;
}

void add_rig_results(py::module_ m) {
  py::class_<Session>(m, "RigSession",
                      "A rig session: the streams a capture recorded, and what it says about them")
      .def_property_readonly("folder", [](const Session& s) { return s.session.folder; })
      .def_property_readonly(
          "complete", [](const Session& s) { return s.session.complete; },
          "False for a .partial folder a killed capture left")
      .def_property_readonly("warnings", [](const Session& s) { return s.session.warnings; })
      .def_property_readonly("tool", [](const Session& s) { return s.session.info.tool; })
      .def_property_readonly("surface", [](const Session& s) { return s.session.info.surface; })
      .def_property_readonly("normal_load_N",
                             [](const Session& s) { return s.session.info.normal_load_N; })
      .def_property_readonly("acceleration_rate_hz",
                             [](const Session& s) { return s.session.info.acceleration_rate_hz; })
      .def_property_readonly("speed_rate_hz",
                             [](const Session& s) { return s.session.info.speed_rate_hz; })
      .def_property_readonly("force_rate_hz",
                             [](const Session& s) { return s.session.info.force_rate_hz; })
      .def_property_readonly(
          "units", [](const Session& s) { return s.session.info.units; },
          "What each stream's numbers mean, e.g. acceleration: 'm/s²' or 'audio full scale'")
      .def_property_readonly(
          "accelerometer_m_s2_per_unit",
          [](const Session& s) { return s.session.info.calibration.accelerometer_m_s2_per_unit; },
          "acceleration × this = m/s²")
      .def_property_readonly(
          "force_counts_per_N",
          [](const Session& s) { return s.session.info.calibration.force_counts_per_N; })
      .def_property_readonly(
          "lever_factor", [](const Session& s) { return s.session.info.calibration.lever_factor; })
      .def_property_readonly(
          "speed_profile", [](const Session& s) { return s.session.info.speed_profile; },
          "What the motor was asked to do, in words")
      .def_property_readonly(
          "profile_time_s",
          [](const py::object& self) {
            const auto& v = of(self).info.profile_time_s;
            return array_view(v.data(), v.size(), self);
          },
          "The profile's breakpoints: times, s (a view; empty when unknown)")
      .def_property_readonly(
          "profile_speed_m_s",
          [](const py::object& self) {
            const auto& v = of(self).info.profile_speed_m_s;
            return array_view(v.data(), v.size(), self);
          },
          "The profile's breakpoints: speeds, m/s (a view)")
      .def_property_readonly("notes", [](const Session& s) { return s.session.info.notes; })
      .def_property_readonly("created_utc",
                             [](const Session& s) { return s.session.info.created_utc; })
      .def_property_readonly(
          "capture", [](const Session& s) { return capture_record(s.session.info); },
          "How the capture went: rig, seconds, frames, dropped_frames, saturated_frames, "
          "fault_frames, "
          "alignment_error_ms, ended_because; None for a session not from a capture")
      .def_property_readonly(
          "acceleration",
          [](const py::object& self) {
            const auto& v = of(self).acceleration;
            return array_view(v.data(), v.size(), self);
          },
          "The acceleration as recorded, in units['acceleration'], at acceleration_rate_hz (a "
          "read-only view)")
      .def_property_readonly(
          "acceleration_m_s2",
          [](const Session& s) {
            const auto& v = s.session.acceleration;
            py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
            auto out = a.mutable_unchecked<1>();
            const double k = s.session.info.calibration.accelerometer_m_s2_per_unit;
            for (std::size_t i = 0; i < v.size(); ++i) out(static_cast<py::ssize_t>(i)) = v[i] * k;
            return a;
          },
          "The acceleration in m/s² (a copy, scaled by accelerometer_m_s2_per_unit)")
      .def_property_readonly(
          "speed_m_s",
          [](const py::object& self) {
            const auto& v = of(self).speed_m_s;
            return array_view(v.data(), v.size(), self);
          },
          "The turntable's speed under the tip, m/s, at speed_rate_hz (a read-only view)")
      .def_property_readonly(
          "normal_force_N",
          [](const py::object& self) {
            const auto& v = of(self).normal_force_N;
            return array_view(v.data(), v.size(), self);
          },
          "N, at force_rate_hz (a read-only view)")
      .def_property_readonly(
          "tangential_force_N",
          [](const py::object& self) {
            const auto& v = of(self).tangential_force_N;
            return array_view(v.data(), v.size(), self);
          },
          "N, at force_rate_hz (a read-only view)")
      .def_property_readonly(
          "frame_times_s",
          [](const Session& s) {
            const auto& i = s.session.info;
            if (i.speed_rate_hz != i.force_rate_hz)
              throw std::invalid_argument(
                  "this session's speed (" + std::to_string(i.speed_rate_hz) + " Hz) and forces (" +
                  std::to_string(i.force_rate_hz) + " Hz) are not one frame stream");
            py::array_t<double> a(static_cast<py::ssize_t>(s.session.speed_m_s.size()));
            auto out = a.mutable_unchecked<1>();
            for (py::ssize_t k = 0; k < a.size(); ++k)
              out(k) = static_cast<double>(k) / i.speed_rate_hz;
            return a;
          },
          "Each sensor frame's instant from the profile's start, s: speed and force sample k at k "
          "/ speed_rate_hz")
      .def(py::pickle(&session_state, &session_of))
      .def("__repr__", [](const Session& s) {
        return "<nibrig.rig.RigSession: " + s.session.info.tool + " on " + s.session.info.surface + ", " +
               std::to_string(s.session.speed_m_s.size()) + " frames" + (s.session.complete ? "" : ", partial") + ">";
      });

  m.def(
      "session",
      [](const std::filesystem::path& folder) {
        ReleasedGil unlocked;
        return Session{model::io::read_rig_session(folder)};
      },
      py::arg("folder"),
      "Reads a session folder (`nibrig rig capture -o`), or the .partial folder a killed capture "
      "left up to its "
      "last block");

  py::class_<Comparison>(m, "Comparison",
                         "A capture compared speed by speed with the simulation driven by its "
                         "measured speed: per speed "
                         "bin the distance of the mean spectra and of the weighted-mean descriptor")
      .def_property_readonly(
          "tool", [](const Comparison& c) { return c.report.tool; }, "The tool measured")
      .def_property_readonly("surface", [](const Comparison& c) { return c.report.surface; })
      .def_property_readonly(
          "simulated", [](const Comparison& c) { return c.simulated; },
          "The simulated tool's name, as the engine gives it")
      .def_property_readonly(
          "simulated_modes", [](const Comparison& c) { return c.simulated_modes; },
          "Whose modes shape the simulated tool")
      .def_property_readonly(
          "session", [](const Comparison& c) -> const Session& { return c.session; },
          "The captured session, read back")
      .def_property_readonly(
          "bins",
          [](const Comparison& c) {
            py::list out;
            for (const auto& b : c.report.bins) {
              py::dict d;
              d["min_speed_m_s"] = b.min_speed_m_s, d["max_speed_m_s"] = b.max_speed_m_s;
              d["mean_speed_m_s"] = b.mean_speed_m_s, d["rows"] = b.rows, d["lsd_db"] = b.lsd_db;
              d["measured_weighted_mean"] = b.measured_weighted_mean,
              d["simulated_weighted_mean"] = b.simulated_weighted_mean;
              d["weighted_mean_log10_difference"] = b.weighted_mean_log10_difference;
              out.append(d);
            }
            return out;
          },
          "The table, a dict per speed bin as comparison.json has it (NaN where a bin has no rows)")
      .def_property_readonly(
          "min_speed_m_s",
          [](const Comparison& c) { return per_bin(c, &model::io::ComparisonBin::min_speed_m_s); },
          "Each speed bin's lower edge, m/s")
      .def_property_readonly(
          "max_speed_m_s",
          [](const Comparison& c) { return per_bin(c, &model::io::ComparisonBin::max_speed_m_s); })
      .def_property_readonly(
          "mean_speed_m_s",
          [](const Comparison& c) { return per_bin(c, &model::io::ComparisonBin::mean_speed_m_s); },
          "The mean measured speed of each bin's rows, m/s (NaN when empty)")
      .def_property_readonly(
          "rows", [](const Comparison& c) { return per_bin(c, &model::io::ComparisonBin::rows); },
          "Spectrogram rows in each bin")
      .def_property_readonly(
          "lsd_db",
          [](const Comparison& c) { return per_bin(c, &model::io::ComparisonBin::lsd_db); },
          "RMS over the band of 20·log10(simulated / measured) of each bin's mean spectra, dB")
      .def_property_readonly("measured_weighted_mean",
                             [](const Comparison& c) {
                               return per_bin(c, &model::io::ComparisonBin::measured_weighted_mean);
                             })
      .def_property_readonly("simulated_weighted_mean",
                             [](const Comparison& c) {
                               return per_bin(c,
                                              &model::io::ComparisonBin::simulated_weighted_mean);
                             })
      .def_property_readonly(
          "weighted_mean_log10_difference",
          [](const Comparison& c) {
            return per_bin(c, &model::io::ComparisonBin::weighted_mean_log10_difference);
          },
          "log10(simulated / measured) of each bin's weighted mean: the space's descriptor's "
          "difference")
      .def_property_readonly(
          "mean_lsd_db", [](const Comparison& c) { return c.report.mean_lsd_db; },
          "Over the bins with rows, each once, dB")
      .def_property_readonly(
          "mean_weighted_mean_log10_difference",
          [](const Comparison& c) { return c.report.mean_weighted_mean_log10_difference; })
      .def_property_readonly("bins_with_rows",
                             [](const Comparison& c) { return c.report.bins_with_rows; })
      .def_property_readonly("rows_analysed",
                             [](const Comparison& c) { return c.report.rows_analysed; })
      .def_property_readonly("rows_outside_speed_range",
                             [](const Comparison& c) { return c.report.rows_outside_speed_range; })
      .def_property_readonly("rows_without_speed",
                             [](const Comparison& c) { return c.report.rows_without_speed; })
      .def_property_readonly(
          "blocks_dropped", [](const Comparison& c) { return c.report.blocks_dropped; },
          "Audio the analysis never saw (its queue was full)")
      .def_property_readonly(
          "band_hz",
          [](const Comparison& c) { return std::pair(c.report.band_min_hz, c.report.band_max_hz); },
          "The frequencies the distances use: low <= f < high, Hz")
      .def_property_readonly(
          "frequencies_hz",
          [](const py::object& self) {
            const auto& v = self.cast<const Comparison&>().frequencies_hz;
            return array_view(v.data(), v.size(), self);
          },
          "The spectrograms' frequencies, Hz (a view)")
      .def_property_readonly(
          "measured_mean", [](const Comparison& c) { return mean_spectra(c, false); },
          "Each bin's mean measured spectrum, bins × frequencies, m/s² peak (a copy)")
      .def_property_readonly(
          "simulated_mean", [](const Comparison& c) { return mean_spectra(c, true); },
          "Each bin's mean simulated spectrum, bins × frequencies, m/s² peak (a copy)")
      .def_property_readonly(
          "waterfall_times_s",
          [](const py::object& self) {
            const auto& v = self.cast<const Comparison&>().rows.times_s;
            return array_view(v.data(), v.size(), self);
          },
          "Each spectrogram row's centre, s (a view)")
      .def_property_readonly(
          "waterfall_speeds_m_s",
          [](const py::object& self) {
            const auto& v = self.cast<const Comparison&>().rows.speeds_m_s;
            return array_view(v.data(), v.size(), self);
          },
          "Each row's mean measured speed, m/s (a view)")
      .def_property_readonly(
          "measured_db", [](const py::object& self) { return waterfall_db(self, false); },
          "The measured spectrogram, rows × frequencies, dB re 1 m/s² peak (a read-only view)")
      .def_property_readonly(
          "simulated_db", [](const py::object& self) { return waterfall_db(self, true); },
          "The simulated spectrogram, rows × frequencies, dB re 1 m/s² peak (a read-only view)")
      .def(
          "save",
          [](const Comparison& c, const std::filesystem::path& file) {
            ReleasedGil unlocked;
            system_refusals([&] { model::io::write_comparison_file(c.report, file); });
          },
          py::arg("path"),
          "Writes comparison.json (FORMATS.md 'Live comparison'), as `nibrig rig compare "
          "--report`, atomically")
      .def(py::pickle(&comparison_state, &comparison_from))
      .def("__repr__", [](const Comparison& c) {
        return "<nibrig.rig.Comparison: " + c.report.tool + " on " + c.report.surface +
               " against " + c.simulated + ", " + std::to_string(c.report.bins_with_rows) +
               " speed bins>";
      });
}

}  // namespace nibrig::ui::python
