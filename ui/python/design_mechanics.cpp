// nibrig.design's mechanics: a design point's modes and frequency response (the FEM step of a
// prediction, model/design/predicted_tool.hpp's simulate_response) and the forcing model a
// Designer predicts with (Sec. 5.2, model/forcing/forcing_model.hpp), its curves and forcing as arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <numbers>

#include "model/design/predicted_tool.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/forcing/forcing_model.hpp"
#include "ui/python/design_types.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/numpy_views.hpp"
#include "ui/python/pickle_state.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace design = model::design;
namespace forcing = model::forcing;

namespace {

struct Modes {
  design::SimulatedResponse response;
  // The forcing model's frequencies, at which the response is: the designer's, or a pickle's own.
  std::shared_ptr<const std::vector<double>> frequencies_hz;
};

Modes modes_of(const Designer& d, const std::string& point) {
  Modes out{{}, {d.inputs, &d.inputs->model.frequencies_hz}};
  run_long_call([&](std::stop_token, const Report&) {
    out.response = design::simulate_response(d.inputs->setup, design::parse_design_point(point));
  }, py::none());
  return out;
}

// A view of one of the Modes' vectors, kept alive by the Python object.
template <typename Get>
auto modes_view(Get get) {
  return [get](const py::object& self) {
    const std::vector<double>& v = get(self.cast<const Modes&>());
    return array_view(v.data(), v.size(), self);
  };
}

struct Forcing {
  std::shared_ptr<const forcing::ForcingModel> held;  // the designer's, or a pickle's own
  const forcing::ForcingModel& model() const { return *held; }
};

constexpr const char* kPickledForcing = "a pickled nibrig.design.Forcing";

// Both pickle as their numbers, the forcing model as its file's text.
py::tuple modes_state(const Modes& x) {
  const auto& r = x.response;
  return py::make_tuple(r.design_name, modal_state(r.modal), r.response_magnitude,
                        *x.frequencies_hz);
}

Modes modes_from(const py::tuple& state) {
  require_state(state, 4, "Modes");
  Modes x;
  x.response.design_name = state[0].cast<std::string>();
  x.response.modal = modal_of(state[1], "Modes");
  x.response.response_magnitude = state[2].cast<std::vector<double>>();
  x.frequencies_hz =
      std::make_shared<const std::vector<double>>(state[3].cast<std::vector<double>>());
  return x;
}

std::vector<double> gain_db(const std::vector<double>& frequencies, const std::function<double(double)>& log_gain) {
  std::vector<double> out;
  for (double f : frequencies) out.push_back(forcing::log_gain_to_db(log_gain(f)));
  return out;
}

}  // namespace

void add_design_mechanics(py::module_ m) {
  py::class_<Modes>(
      m, "Modes",
      "A design's modes and its frequency response from tip force to sensor acceleration")
      .def_property_readonly("design", [](const Modes& x) { return x.response.design_name; })
      .def_property_readonly(
          "frequencies_hz",
          [](const Modes& x) {
            std::vector<double> f;
            for (double w : x.response.modal.omega) f.push_back(w / (2 * std::numbers::pi));
            return f;
          },
          "Undamped frequency of each mode, Hz, ascending")
      .def_property_readonly("damping_ratios", modes_view([](const Modes& x) -> const auto& {
                               return x.response.modal.zeta;
                             }),
                             "ζ of each mode (Rayleigh damping)")
      .def_property_readonly(
          "tip", modes_view([](const Modes& x) -> const auto& { return x.response.modal.input; }),
          "Each mass-normalised mode shape at the tip along the force, kg^-1/2")
      .def_property_readonly("sensor", modes_view([](const Modes& x) -> const auto& {
                               return x.response.modal.output;
                             }),
                             "Each mode shape at the sensor along its axis, kg^-1/2")
      .def_property_readonly(
          "response_frequencies_hz",
          modes_view([](const Modes& x) -> const auto& { return *x.frequencies_hz; }),
          "The frequencies of `response`, Hz (the forcing model's)")
      .def_property_readonly(
          "response",
          modes_view([](const Modes& x) -> const auto& { return x.response.response_magnitude; }),
          "|H(f)|, (m/s²)/N: H(f) = Σ c_i b_i (−Ω²) / (ω_i² − Ω² + 2jζ_i ω_i Ω), Ω = 2πf")
      .def(py::pickle(&modes_state, &modes_from));

  py::class_<Forcing>(m, "Forcing",
                      "The forcing model (Eq. 10): M(f, v) = |H(f)| · F_S(f, v) · t_d(f) · m_μ(f), "
                      "fitted to printed tools")
      .def_property_readonly(
          "frequencies_hz", [](const Forcing& x) { return x.model().frequencies_hz; },
          "Its frequency grid, Hz")
      .def_property_readonly(
          "speeds_m_s", [](const Forcing& x) { return x.model().speeds_m_s; }, "Its speeds, m/s")
      .def_property_readonly("knot_frequencies_hz",
                             [](const Forcing& x) { return x.model().knot_frequencies_hz; })
      .def_property_readonly("surfaces",
                             [](const Forcing& x) {
                               std::vector<std::string> out;
                               for (const auto& [s, _] : x.model().surface_forcing)
                                 out.push_back(s);
                               return out;
                             })
      .def_property_readonly(
          "tips_mm",
          [](const Forcing& x) {
            std::vector<double> out;
            for (const auto& [d, _] : x.model().tip_log_gain) out.push_back(d * 1e3);
            return out;
          },
          "The tip diameters it has gain curves for, mm")
      .def_property_readonly("materials",
                             [](const Forcing& x) {
                               std::vector<std::string> out;
                               for (const auto& [name, _] : x.model().material_log_gain)
                                 out.push_back(name);
                               return out;
                             })
      .def_property_readonly(
          "reference",
          [](const Forcing& x) {
            return py::make_tuple(x.model().reference_tip_diameter_m * 1e3,
                                  x.model().reference_material);
          },
          "(tip in mm, material) whose gains are 1 by definition")
      .def(
          "surface_forcing",
          [](const Forcing& x, const std::string& surface) {
            const auto& all = x.model().surface_forcing;
            const auto found = all.find(surface);
            if (found == all.end())
              throw std::invalid_argument("the forcing model has no surface '" + surface + "'");
            return rows_array(found->second);
          },
          py::arg("surface"), "F_S: speeds x frequencies, N (the force's peak amplitude per bin)")
      .def(
          "tip_gain_db",
          [](const Forcing& x, double tip_mm) {
            return gain_db(x.model().frequencies_hz,
                           [&](double f) { return x.model().tip_log_gain_at(tip_mm * 1e-3, f); });
          },
          py::arg("tip_mm"), "20 log10 t_d(f) at frequencies_hz, dB")
      .def(
          "material_gain_db",
          [](const Forcing& x, const std::string& material) {
            return gain_db(x.model().frequencies_hz,
                           [&](double f) { return x.model().material_log_gain_at(material, f); });
          },
          py::arg("material"), "20 log10 m_μ(f) at frequencies_hz, dB")
      .def(
          "predict",
          [](const Forcing& x, const std::vector<double>& response, const std::string& surface,
             double tip_mm, const std::string& material) {
            return spectrum_array(x.model().predict(response, surface, tip_mm * 1e-3, material));
          },
          py::arg("response"), py::arg("surface"), py::arg("tip_mm"), py::arg("material"),
          "The spectrum a tool with response |H| (at frequencies_hz, (m/s²)/N) measures: speeds x "
          "frequencies, m/s²")
      .def_property_readonly(
          "residual_rms_db", [](const Forcing& x) { return x.model().residual_rms_db; },
          "RMS of 20 log10(model/measured) over every observation of the fit, dB")
      .def_property_readonly(
          "exemplar_fits",
          [](const Forcing& x) {
            py::list out;
            for (const auto& e : x.model().exemplar_fits) {
              py::dict d;
              d["tool"] = e.tool, d["surface"] = e.surface, d["rms_db"] = e.rms_db;
              out.append(d);
            }
            return out;
          },
          "Each printed tool the model was fitted to, with its RMS misfit, dB")
      .def_property_readonly("notes", [](const Forcing& x) { return x.model().notes; })
      .def(py::pickle(
          [](const Forcing& x) { return forcing::forcing_model_text(x.model(), kPickledForcing); },
          [](const std::string& text) {
            return Forcing{std::make_shared<const forcing::ForcingModel>(
                forcing::parse_forcing_model(text, kPickledForcing))};
          }));

  py::object designer = m.attr("Designer");
  designer.attr("modes") = py::cpp_function(
      &modes_of, py::name("modes"), py::is_method(designer), py::sibling(py::getattr(designer, "modes", py::none())),
      py::arg("design"),
      "Meshes and solves a design point's stylus (about a second): its modes and frequency response, as a "
      "prediction solves them");
  designer.attr("forcing") = py::module_::import("builtins")
                                 .attr("property")(py::cpp_function([](const Designer& d) {
                                                     return Forcing{{d.inputs, &d.inputs->model}};
                                                   }),
                                                   py::none(), py::none(),
                                                   "The forcing model this designer predicts with");
}

}  // namespace nibrig::ui::python
