// nibrig.design.calibration_bar and calibrate_ring_down: the first step of calibrating a lab's
// material from prints (`nibrig material calibrate bar|ringdown`), the printed ring-down bar and
// its fit saved among the lab's materials, as library calls (rig/calibration_bar_files.hpp,
// rig/calibration_bar_fit.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>
#include <string>
#include <vector>

#include "model/io/bundled_assets.hpp"
#include "model/io/printer_profile.hpp"
#include "model/mechanics/lab_materials.hpp"
#include "rig/calibration_bar_files.hpp"
#include "rig/calibration_bar_fit.hpp"
#include "ui/python/design_types.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/pickle_state.hpp"

namespace py = pybind11;

namespace nibrig::ui::python {

namespace {

namespace mech = model::mechanics;

// What the Python classes show of a written bar and of a ring-down fit, kept as numbers and names
// so that they pickle (a fit's meshes and linearisation stay in the call that made them).
struct WrittenBar {
  std::string material, printer;
  double length_m = 0.0, volume_m3 = 0.0;
  rig::CalibrationBarFiles files;
};

struct FittedBar {
  std::string name;
  double youngs_modulus_Pa = 0.0, youngs_modulus_sd_Pa = 0.0;
  double rayleigh_stiffness_s = 0.0, rayleigh_stiffness_sd_s = 0.0;
  double first_mode_hz = 0.0, first_mode_damping_ratio = 0.0, relative_residual = 0.0;
  std::vector<double> fitted;
  std::filesystem::path saved;
};

WrittenBar calibration_bar(const std::string& material, const std::string& printer,
                           const std::filesystem::path& folder,
                           const std::optional<double>& length_mm,
                           const std::optional<std::filesystem::path>& materials) {
  const model::io::PrinterProfile profile = model::io::find_printer_profile(printer);
  const mech::MaterialTable table =
      mech::read_material_table(materials.value_or(model::io::default_materials()));
  const rig::CalibrationBar bar = rig::calibration_bar_of(
      material, table, length_mm ? std::optional<double>(*length_mm * 1e-3) : std::nullopt);
  rig::CalibrationBarWritten written;
  run_long_call(
      [&](std::stop_token, const Report&) {
        written = rig::write_calibration_bar(folder, bar, profile, table);
      },
      py::none());
  return {bar.material, profile.name, bar.geometry.length, written.volume_m3, written.files};
}

FittedBar calibrate_ring_down(const std::filesystem::path& trace, const std::filesystem::path& bar,
                              const std::string& name, bool calibrated, bool replace,
                              const std::optional<std::filesystem::path>& materials) {
  rig::SavedBarCalibration saved;
  run_long_call(
      [&](std::stop_token, const Report&) {
        saved = rig::calibrate_and_save_bar(
            bar, trace, name, materials.value_or(std::filesystem::path()), calibrated, replace);
      },
      py::none());
  const auto& fit = saved.result.fit;
  const auto& sd = saved.result.uncertainty;
  return {saved.result.material.name,
          fit.youngs_modulus,
          sd.youngs_modulus_sd,
          fit.rayleigh_stiffness,
          sd.rayleigh_stiffness_sd,
          fit.first_mode_hz,
          fit.first_mode_damping_ratio,
          fit.relative_residual,
          fit.fitted,
          saved.saved};
}

py::tuple bar_state(const WrittenBar& b) {
  const auto& f = b.files;
  return py::make_tuple(
      b.material, b.printer, b.length_m, b.volume_m3,
      py::make_tuple(path_state(f.three_mf), path_state(f.stl), path_state(f.ini),
                     path_state(f.drawing), path_state(f.instructions), path_state(f.record)));
}

WrittenBar bar_of(const py::tuple& state) {
  require_state(state, 5, "CalibrationBar");
  const auto files = state[4].cast<py::tuple>();
  require_state(files, 6, "CalibrationBar");
  const auto file = [&](std::size_t i) { return path_of(files[i]); };
  return {state[0].cast<std::string>(),
          state[1].cast<std::string>(),
          state[2].cast<double>(),
          state[3].cast<double>(),
          {file(0), file(1), file(2), file(3), file(4), file(5)}};
}

py::tuple fitted_bar_state(const FittedBar& f) {
  return py::make_tuple(f.name, f.youngs_modulus_Pa, f.youngs_modulus_sd_Pa, f.rayleigh_stiffness_s,
                        f.rayleigh_stiffness_sd_s, f.first_mode_hz, f.first_mode_damping_ratio,
                        f.relative_residual, f.fitted, f.saved);
}

FittedBar fitted_bar_of(const py::tuple& state) {
  require_state(state, 10, "RingDownCalibration");
  const auto number = [&](std::size_t i) { return state[i].cast<double>(); };
  return {state[0].cast<std::string>(),
          number(1),
          number(2),
          number(3),
          number(4),
          number(5),
          number(6),
          number(7),
          state[8].cast<std::vector<double>>(),
          state[9].cast<std::filesystem::path>()};
}

std::optional<std::filesystem::path> optional_file(const std::filesystem::path& file) {
  if (file.empty()) return std::nullopt;
  return file;
}

}  // namespace

void add_material_calibration(py::module_ m) {
  py::class_<WrittenBar>(m, "CalibrationBar",
                         "The ring-down bar written for a material on a printer")
      .def_property_readonly("material", [](const WrittenBar& b) { return b.material; })
      .def_property_readonly("printer", [](const WrittenBar& b) { return b.printer; })
      .def_property_readonly("length_mm", [](const WrittenBar& b) { return b.length_m * 1e3; })
      .def_property_readonly(
          "volume_mm3", [](const WrittenBar& b) { return b.volume_m3 * 1e9; },
          "Of the meshed solid")
      .def_property_readonly("three_mf", [](const WrittenBar& b) { return b.files.three_mf; })
      .def_property_readonly("stl", [](const WrittenBar& b) { return b.files.stl; })
      .def_property_readonly(
          "ini", [](const WrittenBar& b) { return optional_file(b.files.ini); },
          "PrusaSlicer's settings beside the 3MF (None for a printer PrusaSlicer does not slice)")
      .def_property_readonly("drawing", [](const WrittenBar& b) { return b.files.drawing; })
      .def_property_readonly(
          "instructions", [](const WrittenBar& b) { return b.files.instructions; },
          "How to print, clamp, place the accelerometer, pluck and record (Markdown)")
      .def_property_readonly(
          "record", [](const WrittenBar& b) { return b.files.record; },
          "calibration_bar.json, which calibrate_ring_down reads back")
      .def(py::pickle(&bar_state, &bar_of));

  py::class_<FittedBar>(m, "RingDownCalibration",
                        "A material fitted to its bar's ring-down and saved among the lab's")
      .def_readonly("name", &FittedBar::name)
      .def_readonly("youngs_modulus_Pa", &FittedBar::youngs_modulus_Pa)
      .def_readonly("youngs_modulus_sd_Pa", &FittedBar::youngs_modulus_sd_Pa,
                    "One standard deviation")
      .def_readonly("rayleigh_stiffness_s", &FittedBar::rayleigh_stiffness_s)
      .def_readonly("rayleigh_stiffness_sd_s", &FittedBar::rayleigh_stiffness_sd_s,
                    "One standard deviation")
      .def_readonly("first_mode_hz", &FittedBar::first_mode_hz)
      .def_readonly("first_mode_damping_ratio", &FittedBar::first_mode_damping_ratio)
      .def_readonly("relative_residual", &FittedBar::relative_residual,
                    "‖measured − fitted‖ / ‖measured‖ over the trace")
      .def_property_readonly(
          "fitted",
          [](const FittedBar& f) {
            return py::array_t<double>(static_cast<py::ssize_t>(f.fitted.size()), f.fitted.data());
          },
          "The fitted trace, sample for sample with the recording")
      .def_readonly("saved", &FittedBar::saved,
                    "The lab's file of the material: every call that takes a material by name "
                    "finds it")
      .def(py::pickle(&fitted_bar_state, &fitted_bar_of));

  m.def("calibration_bar", &calibration_bar, py::arg("material"), py::kw_only(), py::arg("printer"),
        py::arg("folder"), py::arg("length_mm") = py::none(), py::arg("materials") = py::none(),
        "Writes the ring-down bar of the paper's Sec. 5.1 in `material` for `printer` (a name or a "
        "profile file) "
        "into `folder`, as `nibrig material calibrate bar` does: 3MF with the slicer settings, "
        "STL, the "
        "PrusaSlicer .ini, drawing, instructions and the record the fit reads. length_mm: shorter "
        "than the paper's "
        "210 mm for a printer whose bed is. A printer that cannot make it raises ValueError naming "
        "every reason.");
  m.def("calibrate_ring_down", &calibrate_ring_down, py::arg("trace"), py::kw_only(),
        py::arg("bar"), py::arg("name"), py::arg("calibrated") = false, py::arg("replace") = false,
        py::arg("materials") = py::none(),
        "Fits the bar's recorded ring-down (a CSV or a session folder) for Young's modulus and "
        "Rayleigh damping "
        "with their uncertainty and saves the material as `name` among the lab's, as `nibrig "
        "material calibrate "
        "ringdown` does. A bundled name, or one the lab has unless replace, is a ValueError before "
        "the fit. "
        "calibrated: the trace is m/s² along the sensor axis (no gain fitted).");
}

}  // namespace nibrig::ui::python
