// The calibration bar's folder (`nibrig material calibrate bar`): the 3MF with the printer's slicer
// settings inside, the STL, the PrusaSlicer .ini beside them, the dimensioned drawing, the
// instructions (how to print, clamp, place the accelerometer, pluck and record) and the record
// `calibration_bar.json` the fit reads back, so that the bar fitted is the bar printed.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "model/io/printer_profile.hpp"
#include "model/mechanics/material_table.hpp"
#include "rig/calibration_bar.hpp"

namespace nibrig::rig {

struct CalibrationBarFiles {
  std::filesystem::path three_mf, stl, ini, drawing, instructions,
      record;  // ini: empty without PrusaSlicer
};

// Where the files go in `folder`.
CalibrationBarFiles calibration_bar_files(const std::filesystem::path& folder,
                                          const model::io::PrinterProfile& printer);

// The instructions, for people (Markdown): every figure from the bar, the printer and the
// material's table values (its predicted first mode, its mass).
std::string calibration_bar_instructions(const CalibrationBar& bar,
                                         const model::io::PrinterProfile& printer,
                                         const model::mechanics::Material& material,
                                         const CalibrationBarFiles& files);

struct CalibrationBarWritten {
  CalibrationBarFiles files;
  nlohmann::json record;
  double volume_m3 = 0.0;  // of the meshed solid
};

// Refuses (model::design::PrintRefused naming the printer and every reason) a bar the printer
// cannot make, and (std::invalid_argument) a material `materials` does not hold; then meshes the
// bar and writes every file atomically as one set into `folder` (made when new; other files left
// alone). Throws std::runtime_error naming a file that cannot be written.
CalibrationBarWritten write_calibration_bar(const std::filesystem::path& folder,
                                            const CalibrationBar& bar,
                                            const model::io::PrinterProfile& printer,
                                            const model::mechanics::MaterialTable& materials);

struct CalibrationBarRecord {
  CalibrationBar bar;
  std::string printer;  // the profile's name
  std::string printer_process;
  std::filesystem::path file;  // the record read
};

// `folder`/calibration_bar.json, or that file named directly. Format "nibrig-calibration-bar",
// version 1. Throws io::FormatError naming the file and field.
CalibrationBarRecord read_calibration_bar(const std::filesystem::path& folder_or_file);

}  // namespace nibrig::rig
