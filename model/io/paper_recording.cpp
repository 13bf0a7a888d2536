#include "model/io/paper_recording.hpp"

#include <algorithm>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::io {
namespace {

constexpr const char* kEitherHeader =
    "time,timestamp,xAccel,yAccel,zAccel,xxx (accelerometer) or TimeStamp,X,Y,Z (friction)";

// The part of a FormatError's message after "<file>: ", to quote it inside another.
std::string problem_of(const FormatError& e) {
  const std::string what = e.what();
  const std::string prefix = e.file().string() + ": ";
  return what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
}

}  // namespace

PaperFormat paper_format_from_header(const std::filesystem::path& file) {
  CsvReader csv(file, kEitherHeader);
  const CsvHeader& header = csv.header();
  const auto& names = header.names();
  if (header.find("timestamp") && header.find("xAccel")) return PaperFormat::vibration;
  if (header.find("TimeStamp") && header.find("Z")) return PaperFormat::friction;
  // Some accelerometer files lost their header names but kept its six columns.
  const bool blank = std::all_of(names.begin(), names.end(),
                                 [](const std::string& name) { return name.empty(); });
  if (blank && names.size() == 6) return PaperFormat::vibration;
  throw FormatError(file, line_place(header.line_number()),
                    std::string("expected the header ") + kEitherHeader);
}

VibrationRecording read_paper_vibration(const std::filesystem::path& file,
                                        const StatedRecording& stated) {
  VibrationFileName name;
  try {
    name = parse_vibration_file_name(file);
    // Material and tip belong to the tool the name gives, not to another one stated instead.
    if (stated.tool && *stated.tool != name.tool) {
      VibrationFileName bare;
      bare.surface = name.surface;
      name = bare;
    }
  } catch (const FormatError& e) {
    if (!stated.tool || !stated.surface)
      throw FormatError(file, "", problem_of(e) + "; or state its tool and surface");
  }
  if (stated.tool) name.tool = *stated.tool;
  if (stated.surface) name.surface = *stated.surface;
  return read_paper_vibration(file, std::move(name));
}

FrictionRecording read_paper_friction(const std::filesystem::path& file,
                                      const StatedRecording& stated) {
  FrictionFileName name;
  try {
    name = parse_friction_file_name(file);
  } catch (const FormatError& e) {
    if (!stated.tool || !stated.surface || !stated.normal_load_N || !stated.lever_factor)
      throw FormatError(file, "",
                        problem_of(e) +
                            "; or state its tool, surface, normal load and lever factor (the "
                            "factor converts the sensor's counts to newtons at the tip)");
    name.repetition = 1;
  }
  if (stated.tool) name.tool = *stated.tool;
  if (stated.surface) name.surface = *stated.surface;
  if (stated.normal_load_N) name.normal_load_N = *stated.normal_load_N;
  if (stated.lever_factor) name.lever_factor = *stated.lever_factor;
  return read_paper_friction(file, std::move(name));
}

}  // namespace nibrig::model::io
