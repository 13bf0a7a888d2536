// nibrig.design.calibration_bar and calibrate_ring_down: the first step of calibrating a lab's
// material from prints (`nibrig material calibrate bar|ringdown`), the printed ring-down bar and
// its fit saved among the lab's materials, as library calls (rig/calibration_bar_files.hpp,
// rig/calibration_bar_fit.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>

#include "model/io/bundled_assets.hpp"
#include "model/io/printer_profile.hpp"
#include "model/mechanics/lab_materials.hpp"
#include "rig/calibration_bar_files.hpp"
#include "rig/calibration_bar_fit.hpp"
#include "ui/python/design_types.hpp"
#include "ui/python/long_call.hpp"

namespace py = pybind11;

namespace nibrig::ui::python {

namespace {

namespace mech = model::mechanics;

struct WrittenBar {
  rig::CalibrationBarWritten written;
  rig::CalibrationBar bar;
  std::string printer;
};

WrittenBar calibration_bar(const std::string& material, const std::string& printer,
                           const std::filesystem::path& folder,
                           const std::optional<double>& length_mm,
                           const std::optional<std::filesystem::path>& materials) {
  const model::io::PrinterProfile profile = model::io::find_printer_profile(printer);
  const mech::MaterialTable table =
      mech::read_material_table(materials.value_or(model::io::default_materials()));
  WrittenBar out;
  out.bar = rig::calibration_bar_of(
      material, table, length_mm ? std::optional<double>(*length_mm * 1e-3) : std::nullopt);
  out.printer = profile.name;
  run_long_call(
      [&](std::stop_token, const Report&) {
        out.written = rig::write_calibration_bar(folder, out.bar, profile, table);
      },
      py::none());
  return out;
}

rig::SavedBarCalibration calibrate_ring_down(
    const std::filesystem::path& trace, const std::filesystem::path& bar, const std::string& name,
    bool calibrated, bool replace, const std::optional<std::filesystem::path>& materials) {
  rig::SavedBarCalibration saved;
  run_long_call(
      [&](std::stop_token, const Report&) {
        saved = rig::calibrate_and_save_bar(
            bar, trace, name, materials.value_or(std::filesystem::path()), calibrated, replace);
      },
      py::none());
  return saved;
}

std::optional<std::filesystem::path> optional_file(const std::filesystem::path& file) {
  if (file.empty()) return std::nullopt;
  return file;
}

}  // namespace

void add_material_calibration(py::module_ m) {
  py::class_<WrittenBar>(m, "CalibrationBar",
                         "The ring-down bar written for a material on a printer")
      .def_property_readonly("material", [](const WrittenBar& b) { return b.bar.material; })
      .def_property_readonly("printer", [](const WrittenBar& b) { return b.printer; })
      .def_property_readonly("length_mm",
                             [](const WrittenBar& b) { return b.bar.geometry.length * 1e3; })
      .def_property_readonly(
          "volume_mm3", [](const WrittenBar& b) { return b.written.volume_m3 * 1e9; },
          "Of the meshed solid")
      .def_property_readonly("three_mf",
                             [](const WrittenBar& b) { return b.written.files.three_mf; })
      .def_property_readonly("stl", [](const WrittenBar& b) { return b.written.files.stl; })
      .def_property_readonly(
          "ini", [](const WrittenBar& b) { return optional_file(b.written.files.ini); },
          "PrusaSlicer's settings beside the 3MF (None for a printer PrusaSlicer does not slice)")
      .def_property_readonly("drawing", [](const WrittenBar& b) { return b.written.files.drawing; })
      .def_property_readonly(
          "instructions", [](const WrittenBar& b) { return b.written.files.instructions; },
          "How to print, clamp, place the accelerometer, pluck and record (Markdown)")
      .def_property_readonly(
          "record", [](const WrittenBar& b) { return b.written.files.record; },
          "calibration_bar.json, which calibrate_ring_down reads back");

  py::class_<rig::SavedBarCalibration>(
      m, "RingDownCalibration",
      "A material fitted to its bar's ring-down and saved among the lab's")
      .def_property_readonly(
          "name", [](const rig::SavedBarCalibration& s) { return s.result.material.name; })
      .def_property_readonly(
          "youngs_modulus_Pa",
          [](const rig::SavedBarCalibration& s) { return s.result.fit.youngs_modulus; })
      .def_property_readonly(
          "youngs_modulus_sd_Pa",
          [](const rig::SavedBarCalibration& s) { return s.result.uncertainty.youngs_modulus_sd; },
          "One standard deviation")
      .def_property_readonly(
          "rayleigh_stiffness_s",
          [](const rig::SavedBarCalibration& s) { return s.result.fit.rayleigh_stiffness; })
      .def_property_readonly(
          "rayleigh_stiffness_sd_s",
          [](const rig::SavedBarCalibration& s) {
            return s.result.uncertainty.rayleigh_stiffness_sd;
          },
          "One standard deviation")
      .def_property_readonly(
          "first_mode_hz",
          [](const rig::SavedBarCalibration& s) { return s.result.fit.first_mode_hz; })
      .def_property_readonly(
          "first_mode_damping_ratio",
          [](const rig::SavedBarCalibration& s) { return s.result.fit.first_mode_damping_ratio; })
      .def_property_readonly(
          "relative_residual",
          [](const rig::SavedBarCalibration& s) { return s.result.fit.relative_residual; },
          "‖measured − fitted‖ / ‖measured‖ over the trace")
      .def_property_readonly(
          "fitted",
          [](const rig::SavedBarCalibration& s) {
            return py::array_t<double>(static_cast<py::ssize_t>(s.result.fit.fitted.size()),
                                       s.result.fit.fitted.data());
          },
          "The fitted trace, sample for sample with the recording")
      .def_property_readonly(
          "saved", [](const rig::SavedBarCalibration& s) { return s.saved; },
          "The lab's file of the material: every call that takes a material by name finds it");

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
