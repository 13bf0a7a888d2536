#include "rig/calibration_bar_fit.hpp"

#include <fmt/format.h>

#include "model/io/bundled_assets.hpp"
#include "model/io/utc_time.hpp"
#include "model/mechanics/lab_materials.hpp"

namespace nibrig::rig {

model::mechanics::RingDownCalibration calibrate_bar(
    const CalibrationBarRecord& bar, const std::filesystem::path& trace, const std::string& name,
    const model::mechanics::MaterialTable& materials, bool calibrated_trace) {
  // The trace first: a wrong file should fail before a minute of meshing, not after.
  const model::io::AccelerationTrace recording = model::io::read_acceleration_trace(trace);
  const model::mechanics::DesignModel model =
      model::mechanics::build_design_model(calibration_bar_design(bar.bar), materials);
  const auto& g = bar.bar.geometry;
  model::mechanics::RingDownCalibrationOptions options;
  options.name = name;
  options.preload = bar.bar.preload;
  options.calibrated = calibrated_trace;
  options.provenance = {
      {"recording", std::filesystem::absolute(trace).lexically_normal().string()},
      {"bar", std::filesystem::absolute(bar.file).lexically_normal().string()},
      {"bar_geometry",
       fmt::format("{:g} x {:g} x {:g} mm, clamped over {:g} mm, {} in {}", g.length * 1e3,
                   g.width * 1e3, g.thickness * 1e3, g.clamp_length * 1e3,
                   g.cutout ? "with its hole" : "no hole", bar.bar.material)},
      // What the printer loads for it: a lab material is its printer's material, calibrated.
      {"printed_as", bar.bar.material},
      {"printer", bar.printer},
      {"printer_process", bar.printer_process},
      {"date", model::io::now_utc_iso8601()}};
  return model::mechanics::calibrate_ring_down(model, recording, options);
}

SavedBarCalibration calibrate_and_save_bar(const std::filesystem::path& bar_folder,
                                           const std::filesystem::path& trace,
                                           const std::string& name,
                                           const std::filesystem::path& materials_file,
                                           bool calibrated_trace, bool replace) {
  const auto file = materials_file.empty() ? model::io::default_materials() : materials_file;
  const model::mechanics::MaterialTable bundled = model::mechanics::read_material_file(file);
  const model::mechanics::MaterialTable materials = model::mechanics::with_lab_materials(bundled);
  const CalibrationBarRecord bar = read_calibration_bar(bar_folder);
  materials.find(bar.bar.material);  // the bar's material must still be in the table
  model::mechanics::check_lab_material_name(name, bundled, replace);
  SavedBarCalibration out;
  out.result = calibrate_bar(bar, trace, name, materials, calibrated_trace);
  out.saved = model::mechanics::save_lab_material(out.result.material, out.result.calibration,
                                                  bundled, replace);
  return out;
}

}  // namespace nibrig::rig
