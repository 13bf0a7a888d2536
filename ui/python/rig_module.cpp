// nibrig.rig: the turntable rig from Python, opened as every face opens it (rig/rig_request.hpp) —
// the simulated rig, a session replayed, the USB controller — a capture into a session folder
// (rig/capture.hpp) and the live comparison with the simulation (rig/comparison_run.hpp), as
// `nibrig rig capture|compare` run them; and a session folder's streams as numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <stop_token>

#include "model/design/tool_sound.hpp"
#include "model/io/atomic_file.hpp"
#include "model/io/comparison_file.hpp"
#include "model/io/finite_output.hpp"
#include "model/io/format_error.hpp"
#include "model/io/rig_session.hpp"
#include "model/numeric/cancellation.hpp"
#include "rig/accelerometer_input.hpp"
#include "rig/capture.hpp"
#include "rig/comparison_run.hpp"
#include "rig/comparison_start.hpp"
#include "rig/rig_request.hpp"
#include "rt/reference_load.hpp"
#include "ui/python/errors.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/pickle_state.hpp"
#include "ui/python/rig_types.hpp"
#include "ui/python/submodules.hpp"
#include "ui/python/tool_sound_options.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;

namespace {

// A rig as asked for: opened afresh by each capture (a rig runs one profile), with what the
// simulation needs (empty: the bundled catalog and stylus, the cached forcing model).
struct RigSpec {
  rig::RigRequest request;
  std::filesystem::path catalog, stylus, forcing;
};

// A refused request as a ValueError naming the argument at fault.
[[noreturn]] void throw_as_argument(const rig::RigRequestRefused& e) {
  using Field = rig::RigRequestRefused::Field;
  const char* argument = rig::field_name(e.field());
  if (e.field() == Field::replay) argument = "path";
  if (e.field() == Field::simulate) argument = "tool";  // compare's: what to simulate
  throw std::invalid_argument(std::string(argument) + ": " + e.what());
}

template <typename Call>
auto rig_refusals(Call&& call) {
  try {
    return system_refusals(std::forward<Call>(call));
  } catch (const rig::RigRequestRefused& e) {
    throw_as_argument(e);
  }
}

RigSpec checked(RigSpec spec) {
  rig_refusals([&] { rig::check_rig_request(spec.request); });
  return spec;
}

// A capture's progress for Python: milliseconds of acceleration recorded, of the profile's. (Ctrl-C
// reaches the capture as the long call's stop token: the motor stops and the session is finished
// with what it holds.)
struct CaptureProgressReport {
  std::uint64_t samples = 0;

  std::function<void(const rig::RigData&)> counter(const rig::Rig& r, const rig::SpeedProfile& profile, const Report& report) {
    const double rate = r.description().acceleration_rate_hz;
    const auto total = static_cast<std::size_t>(std::llround(profile.duration_s() * 1e3));
    return [this, rate, total, report](const rig::RigData& data) {
      samples += data.acceleration.size();
      report("capturing", std::min(total, static_cast<std::size_t>(std::llround(static_cast<double>(samples) / rate * 1e3))),
             total);
    };
  }
};

Session capture(const RigSpec& spec, const std::filesystem::path& folder, const std::optional<std::filesystem::path>& profile,
                const std::optional<double>& seconds, const std::string& notes, const py::object& progress) {
  Session out;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        model::design::ToolSounds sounds(tool_sound_options(spec.catalog, spec.stylus, spec.forcing, stop, report));
        rig::OpenedRig opened = rig_refusals([&] {
          return rig::open_rig_with_profile(spec.request, sounds, profile ? profile->string() : "",
                                            "steps", seconds);
        });
        model::numeric::throw_if_cancelled(stop, "rig capture");  // stopped before it began: no folder
        CaptureProgressReport recorded;
        rig::CaptureOptions options;
        options.folder = folder;
        options.tool = spec.request.tool;
        options.surface = spec.request.surface;
        options.notes = notes;
        options.cancel = stop;
        options.on_data = recorded.counter(*opened.rig, opened.profile, report);
        const auto result = system_refusals([&] { return rig::capture_session(*opened.rig, opened.profile, options); });
        out.session = model::io::read_rig_session(result.folder);
      },
      progress);
  return out;
}

Comparison compare(const RigSpec& spec, const std::optional<std::string>& tool, const std::filesystem::path& folder,
                   const std::optional<std::string>& surface, const std::optional<std::filesystem::path>& profile,
                   const std::optional<double>& seconds, std::uint64_t seed, const std::optional<std::filesystem::path>& catalog,
                   const std::optional<std::filesystem::path>& stylus, const std::optional<std::filesystem::path>& forcing,
                   const py::object& progress) {
  Comparison out;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        rig::ComparisonRequest request;
        request.rig = spec.request;
        request.profile = profile ? profile->string() : "";
        request.seconds = seconds;
        request.simulate = tool.value_or("");
        request.simulate_surface = surface.value_or("");
        request.sounds = tool_sound_options(spec.catalog, spec.stylus, spec.forcing, stop, report);
        // The rig's own inputs unless others are given (the simulated rig's tool sounds as it
        // simulates).
        if (catalog || stylus || forcing)
          request.simulation_sounds =
              tool_sound_options(catalog.value_or(spec.catalog), stylus.value_or(spec.stylus),
                                 forcing.value_or(spec.forcing), stop, report);
        request.session = folder;
        request.seed = seed;
        std::optional<rig::ComparisonStart> start;
        rig_refusals([&] {
          start.emplace(std::move(request));
          start->open();
        });
        model::numeric::throw_if_cancelled(stop, "rig comparison");  // stopped before it began: no folder
        CaptureProgressReport recorded;
        rig::ComparisonHooks hooks;
        hooks.cancel = stop;
        hooks.on_data = recorded.counter(start->rig(), start->profile(), report);
        auto run = system_refusals([&] { return start->run(hooks); });
        const auto folder = run.capture.folder;
        auto written = start->report(run);
        out = comparison_of(std::move(run), std::move(written), start->simulated().modes);
        out.session.session = model::io::read_rig_session(folder);
      },
      progress);
  return out;
}

std::optional<std::string> or_none(const std::string& s) { return s.empty() ? std::nullopt : std::optional(s); }

// A rig as asked for, as its request and files; opening it checks them again, as for a new one.
py::tuple rig_spec_state(const RigSpec& r) {
  const auto& q = r.request;
  return py::make_tuple(
      static_cast<int>(q.kind), q.tool, q.surface, q.load_N, q.seed, q.speedup,
      path_state(q.replay), path_state(q.replay_friction), q.usb_serial, q.input_api,
      q.input_device, q.input_channel, q.accelerometer_m_s2_per_full_scale,
      py::make_tuple(path_state(r.catalog), path_state(r.stylus), path_state(r.forcing)));
}

RigSpec rig_spec_of(const py::tuple& state) {
  require_state(state, 14, "Rig");
  const int kind = state[0].cast<int>();
  if (kind < static_cast<int>(rig::RigKind::simulated) ||
      kind > static_cast<int>(rig::RigKind::replay))
    throw std::invalid_argument("Rig: not a pickled Rig");
  RigSpec r;
  auto& q = r.request;
  q.kind = static_cast<rig::RigKind>(kind);
  q.tool = state[1].cast<std::string>(), q.surface = state[2].cast<std::string>();
  q.load_N = state[3].cast<double>(), q.seed = state[4].cast<std::uint64_t>();
  q.speedup = state[5].cast<double>();
  q.replay = path_of(state[6]);
  q.replay_friction = path_of(state[7]);
  q.usb_serial = state[8].cast<std::string>();
  q.input_api = state[9].cast<std::string>(), q.input_device = state[10].cast<std::string>();
  q.input_channel = state[11].cast<unsigned>();
  q.accelerometer_m_s2_per_full_scale = state[12].cast<double>();
  const auto files = state[13].cast<py::tuple>();
  require_state(files, 3, "Rig");
  r.catalog = path_of(files[0]);
  r.stylus = path_of(files[1]);
  r.forcing = path_of(files[2]);
  return r;
}

}  // namespace

void add_rig_module(py::module_ m) {
  add_rig_results(m);

  py::class_<RigSpec>(m, "Rig", "A rig as asked for; each capture or comparison opens it afresh")
      .def_property_readonly(
          "kind",
          [](const RigSpec& r) {
            switch (r.request.kind) {
              case rig::RigKind::simulated:
                return "simulated";
              case rig::RigKind::replay:
                return "replay";
              case rig::RigKind::usb:
                return "usb";
            }
            return "";
          },
          "'simulated', 'replay' or 'usb'")
      .def_property_readonly(
          "tool", [](const RigSpec& r) { return or_none(r.request.tool); },
          "What is mounted (None: what the rig knows, a replayed session's own)")
      .def_property_readonly("surface", [](const RigSpec& r) { return or_none(r.request.surface); })
      .def_property_readonly(
          "load_N", [](const RigSpec& r) { return r.request.load_N; }, "The arm's normal load, N")
      .def_property_readonly(
          "seed", [](const RigSpec& r) { return r.request.seed; }, "The simulated rig's noise")
      .def_property_readonly(
          "speedup", [](const RigSpec& r) { return r.request.speedup; },
          "1 = real time, k = k times faster, 0 = as fast as it computes (simulated, replay)")
      .def_property_readonly(
          "path",
          [](const RigSpec& r) {
            return r.request.kind == rig::RigKind::replay ? py::cast(r.request.replay) : py::none();
          },
          "The replayed session or recording")
      .def_property_readonly("serial",
                             [](const RigSpec& r) { return or_none(r.request.usb_serial); })
      .def(py::pickle(&rig_spec_state, &rig_spec_of))
      .def("__repr__", [](const RigSpec& r) {
        switch (r.request.kind) {
          case rig::RigKind::simulated:
            return "<nibrig.rig.Rig: simulated, " + r.request.tool + " on " + r.request.surface + ">";
          case rig::RigKind::replay:
            return "<nibrig.rig.Rig: replay of " + r.request.replay.string() + ">";
          case rig::RigKind::usb:
            return "<nibrig.rig.Rig: USB controller " + (r.request.usb_serial.empty() ? "(the only one)" : r.request.usb_serial) + ">";
        }
        return std::string("<nibrig.rig.Rig>");
      });

  m.def(
      "simulated",
      [](const std::string& tool, const std::string& surface, double load, std::uint64_t seed,
         double speedup, const std::optional<std::filesystem::path>& catalog,
         const std::optional<std::filesystem::path>& stylus,
         const std::optional<std::filesystem::path>& forcing) {
        RigSpec r;
        r.request.kind = rig::RigKind::simulated;
        r.request.tool = tool, r.request.surface = surface;
        r.request.load_N = load, r.request.seed = seed, r.request.speedup = speedup;
        r.catalog = catalog.value_or(std::filesystem::path());
        r.stylus = stylus.value_or(std::filesystem::path());
        r.forcing = forcing.value_or(std::filesystem::path());
        return checked(r);  // here, not first when a capture opens it
      },
      py::arg("tool"), py::arg("surface"), py::kw_only(),
      py::arg("load") = rt::kReferenceNormalForce, py::arg("seed") = 1u, py::arg("speedup") = 0.0,
      py::arg("catalog") = py::none(), py::arg("stylus") = py::none(),
      py::arg("forcing") = py::none(),
      "The simulated rig: the engine's simulation of a tool (catalog id or design point) on a "
      "surface, pressed "
      "with `load` N; its noise fixed by `seed`; speedup 0 computes as fast as it can (1: real "
      "time). catalog, "
      "stylus, forcing: what the simulation is made from (default: the bundled ones, the cached "
      "forcing model).");
  m.def(
      "replay",
      [](const std::filesystem::path& path, double speedup) {
        RigSpec r;
        r.request.kind = rig::RigKind::replay;
        r.request.replay = path;
        r.request.speedup = speedup;
        return checked(r);
      },
      py::arg("path"), py::kw_only(), py::arg("speedup") = 0.0,
      "A recorded session folder (or one of the paper's arm_*.csv recordings) replayed as if live, "
      "with the "
      "profile it recorded; speedup 0 as fast as it reads (1: real time)");
  m.def(
      "usb",
      [](const std::optional<std::string>& serial, const std::optional<std::string>& input_api,
         const std::optional<std::string>& input_device, unsigned input_channel,
         double accelerometer, const std::optional<std::string>& tool,
         const std::optional<std::string>& surface, double load) {
        RigSpec r;
        r.request.kind = rig::RigKind::usb;
        r.request.usb_serial = serial.value_or("");
        r.request.input_api = input_api.value_or("");
        r.request.input_device = input_device.value_or("");
        r.request.input_channel = input_channel;
        r.request.accelerometer_m_s2_per_full_scale = accelerometer;
        r.request.tool = tool.value_or(""), r.request.surface = surface.value_or("");
        r.request.load_N = load;
        return checked(r);
      },
      py::kw_only(), py::arg("serial") = py::none(), py::arg("input_api") = py::none(),
      py::arg("input_device") = py::none(), py::arg("input_channel") = 1u,
      py::arg("accelerometer") = rig::kDefaultAccelerometerM_s2, py::arg("tool") = py::none(),
      py::arg("surface") = py::none(), py::arg("load") = rt::kReferenceNormalForce,
      "The USB rig controller (by serial; None: the only one on the bus) with the accelerometer on "
      "an audio input "
      "(input_api: jack, alsa, pulse; input_device by name; input_channel 1-based; accelerometer: "
      "its m/s² at full "
      "scale); tool and surface: what is mounted, which a session must say. Opened by capture or "
      "compare: a "
      "missing controller or input is an OSError naming what was asked.");

  m.def("capture", &capture, py::arg("rig"), py::arg("folder"), py::kw_only(), py::arg("profile") = py::none(),
        py::arg("seconds") = py::none(), py::arg("notes") = "", py::arg("progress") = py::none(),
        "Runs a speed profile on the rig and records a session into `folder` (<folder>.partial while recording), as "
        "`nibrig rig capture` does; returns it read back. profile: 'steps' (the default, the paper's 42 s), 'sweep' "
        "(the study's 3 s sweep, 6 s) or a CSV file time_s,speed_mm_s; a replay runs what was recorded. seconds cuts "
        "or repeats it. progress: ('capturing', ms recorded, ms of the profile). Releases the GIL; Ctrl-C stops the "
        "motor, finishes the session with what it holds, then raises KeyboardInterrupt. A folder that exists is an "
        "OSError.");
  m.def("compare", &compare, py::arg("rig"), py::arg("tool"), py::arg("folder"), py::kw_only(), py::arg("surface") = py::none(),
        py::arg("profile") = py::none(), py::arg("seconds") = py::none(), py::arg("seed") = 1u,
        py::arg("catalog") = py::none(), py::arg("stylus") = py::none(), py::arg("forcing") = py::none(),
        py::arg("progress") = py::none(),
        "Captures on the rig into the session `folder` while simulating `tool` (a catalog id or design point; None: "
        "what is mounted) on `surface` (None: the mounted one) driven by the measured speed and force, and compares "
        "their spectrograms per speed bin, as `nibrig rig compare` does (its session is <report>/session; save() "
        "writes its comparison.json). profile defaults to 'sweep' (6 s); seed: the simulation's forcing noise. "
        "Releases the GIL; Ctrl-C as for capture.");
}

}  // namespace nibrig::ui::python
