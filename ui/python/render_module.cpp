// nibrig.render: a tool (a catalog tool or a design point) on a surface, moved at a constant speed,
// along the rig's sweep or an artist's drawing, rendered offline through the real-time engine —
// the same render() the audio callback calls — into a numpy array, as `nibrig render` into a WAV.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>

#include "model/design/tool_sound.hpp"
#include "model/numeric/cancellation.hpp"
#include "playback/offline_render.hpp"
#include "playback/prepared_engine.hpp"
#include "rt/reference_load.hpp"
#include "rt/stroke_request.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/numpy_views.hpp"
#include "ui/python/pickle_state.hpp"
#include "ui/python/submodules.hpp"
#include "ui/python/tool_sound_options.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;

namespace {

struct Rendering {
  std::vector<float> samples;
  double rate_hz = 0.0;
  std::string tool, stroke;  // what played and how it moved, in words
};

Rendering render_tool(const std::string& tool, const std::string& surface, const std::optional<double>& speed_m_s,
                      const std::optional<std::filesystem::path>& trajectory, const std::optional<double>& force_n,
                      const std::optional<double>& seconds, double rate_hz, std::size_t period, std::uint64_t seed,
                      const std::optional<std::filesystem::path>& catalog, const std::optional<std::filesystem::path>& stylus,
                      const std::optional<std::filesystem::path>& forcing, const py::object& progress) {
  // The library's ranges, as the command line's, before any meshing or fitting.
  playback::check_render_rate(rate_hz, "rate_hz");
  playback::check_render_block(period, "period");
  if (seconds) playback::check_render_seconds(*seconds, "seconds");
  rt::StrokeRequest request;
  request.speed_m_s = speed_m_s;
  request.trajectory = trajectory.value_or(std::filesystem::path());
  request.force_n = force_n;
  playback::check_stroke_request(request);
  Rendering out;
  out.rate_hz = rate_hz;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        const auto options = tool_sound_options(catalog, stylus, forcing, stop, report);
        model::design::ToolSounds sounds(options);
        sounds.check(tool, surface);  // before any meshing or fitting
        rt::Stroke stroke = rt::make_stroke(request);
        const auto sound = sounds.sound(tool, surface);
        rt::EngineSettings settings;
        settings.sample_rate_hz = rate_hz;
        playback::PreparedEngine session(settings, sound, std::move(stroke.source), seed);
        out.tool = session.names().front();
        out.stroke = stroke.description;
        const auto frames = static_cast<std::size_t>(std::llround(seconds.value_or(stroke.natural_seconds) * rate_hz));
        out.samples.assign(frames, 0.0f);
        for (std::size_t at = 0; at < frames; at += period) {
          model::numeric::throw_if_cancelled(stop, "render");
          session.engine().render(out.samples.data() + at, std::min(period, frames - at));
          report("rendering", std::min(at + period, frames), frames);
        }
      },
      progress);
  return out;
}

}  // namespace

void add_render_module(py::module_ m) {
  py::class_<Rendering>(m, "Rendering", "A tool rendered offline: the actuator's drive signal")
      .def_property_readonly(
          "samples",
          [](const py::object& self) {
            const auto& r = self.cast<const Rendering&>();
            return array_view(r.samples.data(), r.samples.size(), self);
          },
          "Mono samples, full scale ±1 (the engine's output level per m/s² of sensor "
          "acceleration); a read-only view")
      .def_readonly("rate_hz", &Rendering::rate_hz)
      .def_readonly("tool", &Rendering::tool, "What played, as the engine names it")
      .def_readonly("stroke", &Rendering::stroke, "How it moved, in words")
      .def("__len__", [](const Rendering& r) { return r.samples.size(); })
      .def(py::pickle(
          [](const Rendering& r) {
            return py::make_tuple(float_bytes(r.samples), r.rate_hz, r.tool, r.stroke);
          },
          [](const py::tuple& state) {
            require_state(state, 4, "Rendering");
            return Rendering{floats_of(state[0], "Rendering"), state[1].cast<double>(),
                             state[2].cast<std::string>(), state[3].cast<std::string>()};
          }));

  const std::string tool_doc = fmt::format(
      "Renders a catalog tool ('cryon') or a design point ('DM85:0.5,vero:0.5,tip=2mm') on a "
      "surface as "
      "`nibrig render` does: speed in m/s (constant), or trajectory (an artist's drawing file), "
      "else the "
      "rig's sweep 17-250 mm/s; force in N (default {:g}, the paper's); seconds (default: two "
      "sweep "
      "periods, the drawing's length or 5 s); blocks of `period` frames as a device would ask; the "
      "same "
      "seed gives the same samples. Releases the GIL; Ctrl-C stops it.",
      rt::kReferenceNormalForce);
  m.def("tool", &render_tool, py::arg("tool"), py::arg("surface"), py::kw_only(),
        py::arg("speed") = py::none(), py::arg("trajectory") = py::none(),
        py::arg("force") = py::none(), py::arg("seconds") = py::none(),
        py::arg("rate_hz") = 48000.0, py::arg("period") = 64, py::arg("seed") = 1u,
        py::arg("catalog") = py::none(), py::arg("stylus") = py::none(),
        py::arg("forcing") = py::none(), py::arg("progress") = py::none(), tool_doc.c_str());
}

}  // namespace nibrig::ui::python
