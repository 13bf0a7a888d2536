// A pen's calibration file (JSON, "nibrig-pen" version 1) and where each pen's is kept: one file
// per pen name, as the actuators' (playback/actuator_store.hpp), in $NIBRIG_PENS, else
// $XDG_DATA_HOME/nibrig/pens, else ~/.local/share/nibrig/pens.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "rig/pen/pen_force.hpp"

namespace nibrig::rig::pen {

// One load held during the calibration, kept in the file beside the curve so that a reader sees
// what the curve was made from.
struct PenHold {
  double force_n = 0.0;
  double pressure = 0.0;     // the mean over the steady window
  double pressure_sd = 0.0;  // its standard deviation there
  std::size_t samples = 0;
};

struct PenCalibration {
  std::string name;
  std::string created;  // ISO 8601 (model/io/utc_time.hpp); the writer fills it in when empty
  std::string method;   // how the loads were known, e.g. "kitchen scale"; may be empty
  std::vector<PenHold> holds;
  PressureCurve curve = default_pressure_curve();
};

// Throws std::runtime_error naming the file when it cannot be written.
void write_pen_file(const std::filesystem::path& file, const PenCalibration& calibration);

// Throws model::io::FormatError naming the file, the JSON path of the bad field and what was
// expected.
PenCalibration read_pen_file(const std::filesystem::path& file);

std::filesystem::path pen_folder();
// <folder>/<name>.json, the name made safe for a file name (anything but letters, digits, '-', '_'
// and '.' becomes '_').
std::filesystem::path pen_curve_path(const std::string& name);

// The curve a pen plays with: its stored calibration, or the default when it has none (a face says
// "default" then). A stored file that cannot be read throws (FormatError): a broken calibration is
// never replaced by the default unnoticed.
struct PenCurveChoice {
  PressureCurve curve = default_pressure_curve();
  bool is_default = true;
  std::filesystem::path file;  // the file read; empty for the default
};
PenCurveChoice pen_curve_for(const std::string& name);

}  // namespace nibrig::rig::pen
