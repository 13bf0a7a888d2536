// Step 2 of calibrating a material from prints: the ring-down recorded on a printed calibration bar
// (rig/calibration_bar_files.hpp) fitted for the material's modulus and damping, with what it was
// fitted from, ready to be saved among the lab's materials (model/mechanics/lab_materials.hpp).
#pragma once

#include <filesystem>
#include <string>

#include "model/mechanics/ring_down_calibration.hpp"
#include "rig/calibration_bar_files.hpp"

namespace nibrig::rig {

// Builds the bar's FEM model with its material's table values (`materials`), reads `trace`
// (model/io/acceleration_trace.hpp: CSV or a session folder) and fits it; the provenance names the
// recording, the bar's record and geometry, the printer profile and the time. Throws what reading,
// building and fitting throw, each naming its file.
model::mechanics::RingDownCalibration calibrate_bar(
    const CalibrationBarRecord& bar, const std::filesystem::path& trace, const std::string& name,
    const model::mechanics::MaterialTable& materials, bool calibrated_trace = false);

struct SavedBarCalibration {
  model::mechanics::RingDownCalibration result;
  std::filesystem::path saved;  // the lab's file of the material
};

// The whole step, as every face runs it: the bar's record read from `bar_folder` (or its file), the
// name checked against the bundled table `materials_file` (empty: assets/materials.json) and the
// lab's store (a name it holds is refused unless `replace`), and the bar's material found in the
// table, all before the fit, which takes seconds of meshing; then calibrate_bar, and the material
// saved among the lab's (basis fitted). Throws what those throw, each naming its file or name.
SavedBarCalibration calibrate_and_save_bar(const std::filesystem::path& bar_folder,
                                           const std::filesystem::path& trace,
                                           const std::string& name,
                                           const std::filesystem::path& materials_file,
                                           bool calibrated_trace, bool replace);

}  // namespace nibrig::rig
