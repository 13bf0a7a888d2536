// nibrig.design's calibrations (issue 47): a new material's curve from a few of its prints, or a
// new surface's forcing from a few tools the model knows, each against a forcing model the lab has
// (model/forcing/material_calibration.hpp, surface_calibration.hpp), as `nibrig forcing
// calibrate-material --forcing` and `calibrate-surface --forcing` do. The prints are a catalog's.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>
#include <tuple>

#include "model/forcing/calibration_prints.hpp"
#include "model/forcing/forcing_file.hpp"
#include "model/forcing/forcing_inputs.hpp"
#include "model/forcing/forcing_store.hpp"
#include "model/forcing/material_calibration.hpp"
#include "model/forcing/surface_calibration.hpp"
#include "model/numeric/cancellation.hpp"
#include "ui/python/design_types.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/pickle_state.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace forcing = model::forcing;

namespace {

// What either calibration gives a scientist: the model with the new curve or forcing, and the
// numbers that say how sure it is.
struct Calibration {
  forcing::ForcingModel model;
  std::string name;                         // the material or the surface
  std::vector<double> gain_db, gain_se_db;  // material: per knot
  double rms_se_db = 0.0;                   // surface: RMS of its cells' SE
  std::size_t prints = 0, exemplars = 0;
  double degrees_of_freedom = 0.0;
  double residual_rms_db = 0.0;
  std::vector<forcing::ExemplarFit> fits, predicted;
};

py::list fits_list(const std::vector<forcing::ExemplarFit>& fits) {
  py::list out;
  for (const auto& f : fits)
    out.append(py::dict(py::arg("tool") = f.tool, py::arg("surface") = f.surface,
                        py::arg("rms_db") = f.rms_db));
  return out;
}

// The catalog's prints with their simulated responses on the held model's grid, at the resolution
// it was fitted with (modes and mesh_size as the stylus template's when 0).
forcing::ForcingInputs catalog_inputs(const forcing::ForcingModel& against,
                                      const std::optional<std::filesystem::path>& catalog,
                                      int modes, double mesh_size, const py::object& progress) {
  forcing::ForcingInputOptions options;
  options.catalog = catalog.value_or(std::filesystem::path());
  options.modes = modes;
  options.mesh_size = mesh_size;
  options.frequencies_hz = against.frequencies_hz;
  forcing::check_forcing_input_options(options);
  forcing::ForcingInputs inputs;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        inputs = forcing::load_forcing_inputs(
            options, [&](const forcing::DesignResponse&, std::size_t done, std::size_t total) {
              model::numeric::throw_if_cancelled(stop, "calibration");
              report("simulating the catalog's designs", done, total);
            });
      },
      progress);
  return inputs;
}

Calibration calibrate_material(const std::string& material, const std::filesystem::path& against,
                               const std::optional<std::vector<double>>& tips_mm,
                               const std::optional<std::filesystem::path>& catalog, int modes,
                               double mesh_size, const py::object& progress) {
  const forcing::ForcingModel model =
      forcing::read_forcing_model(forcing::find_forcing_model(against.string()));
  const forcing::ForcingInputs inputs = catalog_inputs(model, catalog, modes, mesh_size, progress);
  std::vector<double> tips;
  for (double mm : tips_mm.value_or(std::vector<double>{})) tips.push_back(mm * 1e-3);
  const auto prints = forcing::prints_of_material(inputs.exemplars, material, tips);
  const forcing::MaterialCalibration c = forcing::calibrate_material(model, prints, material);
  Calibration out{c.model,
                  material,
                  {},
                  {},
                  0.0,
                  c.prints,
                  c.exemplars,
                  c.degrees_of_freedom,
                  c.residual_rms_db,
                  c.print_fits,
                  forcing::unused_print_errors(c.model, inputs.exemplars, material, prints)};
  for (double g : c.log_gain) out.gain_db.push_back(forcing::log_gain_to_db(g));
  for (double se : c.log_gain_se) out.gain_se_db.push_back(forcing::log_gain_to_db(se));
  return out;
}

Calibration calibrate_surface(const std::string& surface, const std::filesystem::path& against,
                              const std::optional<std::vector<std::string>>& tools,
                              const std::optional<std::filesystem::path>& catalog, int modes,
                              double mesh_size, const py::object& progress) {
  const forcing::ForcingModel model =
      forcing::read_forcing_model(forcing::find_forcing_model(against.string()));
  const forcing::ForcingInputs inputs = catalog_inputs(model, catalog, modes, mesh_size, progress);
  const auto named = tools.value_or(std::vector<std::string>{});
  const auto used = forcing::tools_on_surface(inputs.exemplars, surface, named);
  const forcing::SurfaceCalibration c = forcing::calibrate_surface(model, used, surface);
  return {c.model, surface,           {},          {}, c.rms_se_db, used.size(), used.size(),
          0.0,     c.residual_rms_db, c.tool_fits, {}};
}

constexpr const char* kPickledCalibration = "a pickled nibrig.design.Calibration";

// A calibration pickles as its numbers, its model as the forcing file's text.
py::tuple calibration_state(const Calibration& c) {
  const auto fits = [](const std::vector<forcing::ExemplarFit>& all) {
    std::vector<py::tuple> out;
    for (const auto& f : all) out.push_back(py::make_tuple(f.tool, f.surface, f.rms_db));
    return out;
  };
  return py::make_tuple(forcing::forcing_model_text(c.model, kPickledCalibration), c.name,
                        c.gain_db, c.gain_se_db, c.rms_se_db, c.prints, c.exemplars,
                        c.degrees_of_freedom, c.residual_rms_db, fits(c.fits), fits(c.predicted));
}

Calibration calibration_of(const py::tuple& state) {
  require_state(state, 11, "Calibration");
  const auto fits = [](const py::handle& all) {
    std::vector<forcing::ExemplarFit> out;
    for (const auto& [tool, surface, rms_db] :
         all.cast<std::vector<std::tuple<std::string, std::string, double>>>())
      out.push_back({tool, surface, rms_db});
    return out;
  };
  return {forcing::parse_forcing_model(state[0].cast<std::string>(), kPickledCalibration),
          state[1].cast<std::string>(),
          state[2].cast<std::vector<double>>(),
          state[3].cast<std::vector<double>>(),
          state[4].cast<double>(),
          state[5].cast<std::size_t>(),
          state[6].cast<std::size_t>(),
          state[7].cast<double>(),
          state[8].cast<double>(),
          fits(state[9]),
          fits(state[10])};
}

}  // namespace

void add_forcing_calibration(py::module_ m) {
  py::class_<Calibration>(
      m, "Calibration",
      "A material's curve or a surface's forcing calibrated against a forcing model")
      .def_property_readonly(
          "name", [](const Calibration& c) { return c.name; }, "The material or the surface")
      .def_property_readonly("knot_frequencies_hz",
                             [](const Calibration& c) { return c.model.knot_frequencies_hz; })
      .def_property_readonly(
          "gain_db", [](const Calibration& c) { return c.gain_db; },
          "A material's 20 log10 m(f) at the knots, dB (empty for a surface)")
      .def_property_readonly(
          "gain_se_db", [](const Calibration& c) { return c.gain_se_db; },
          "Its standard error at each knot, dB (between prints included)")
      .def_property_readonly(
          "rms_se_db", [](const Calibration& c) { return c.rms_se_db; },
          "A surface's forcing: RMS over its cells of the standard error, dB (0 from one tool)")
      .def_property_readonly(
          "prints", [](const Calibration& c) { return c.prints; }, "Distinct prints (tools) used")
      .def_property_readonly(
          "exemplars", [](const Calibration& c) { return c.exemplars; }, "Recordings used")
      .def_property_readonly(
          "degrees_of_freedom", [](const Calibration& c) { return c.degrees_of_freedom; },
          "Of a material's knot intervals (0 for a surface)")
      .def_property_readonly(
          "residual_rms_db", [](const Calibration& c) { return c.residual_rms_db; },
          "How far the calibration is from what it was calibrated on, dB RMS")
      .def_property_readonly(
          "fits", [](const Calibration& c) { return fits_list(c.fits); },
          "Per print (or tool) calibrated on: tool, surface, rms_db")
      .def_property_readonly(
          "predicted", [](const Calibration& c) { return fits_list(c.predicted); },
          "A material's other prints in the catalog, predicted: tool, surface, rms_db")
      .def(
          "save",
          [](const Calibration& c, const std::filesystem::path& file) {
            run_long_call([&](std::stop_token,
                              const Report&) { forcing::write_forcing_model(file, c.model); },
                          py::none());
          },
          py::arg("path"), "Writes the calibrated forcing model (forcing.json), atomically")
      .def(
          "keep",
          [](const Calibration& c, const std::string& name, bool replace) {
            std::filesystem::path kept;
            run_long_call(
                [&](std::stop_token, const Report&) {
                  kept = forcing::save_forcing_model(name, c.model, replace);
                },
                py::none());
            return kept;
          },
          py::arg("name"), py::kw_only(), py::arg("replace") = false,
          "Keeps the calibrated model by name in the lab's store (designer(forcing=name) finds "
          "it); returns its file")
      .def(py::pickle(&calibration_state, &calibration_of));
  m.def("calibrate_material", &calibrate_material, py::arg("material"), py::kw_only(),
        py::arg("forcing"), py::arg("tips_mm") = py::none(), py::arg("catalog") = py::none(),
        py::arg("modes") = 0, py::arg("mesh_size") = 0.0, py::arg("progress") = py::none(),
        "A new material's curve from its prints in the catalog (only those tips when given), "
        "against the forcing "
        "model named or filed (`nibrig forcing calibrate-material --forcing`)");
  m.def("calibrate_surface", &calibrate_surface, py::arg("surface"), py::kw_only(),
        py::arg("forcing"), py::arg("tools") = py::none(), py::arg("catalog") = py::none(),
        py::arg("modes") = 0, py::arg("mesh_size") = 0.0, py::arg("progress") = py::none(),
        "A new surface's forcing from the tools measured on it in the catalog (only those named "
        "when given), against "
        "the forcing model named or filed (`nibrig forcing calibrate-surface --forcing`)");
}

}  // namespace nibrig::ui::python
