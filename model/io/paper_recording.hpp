// One of the paper's recordings under any file name: which of its two formats the file holds, from
// the header line when the name does not say, and which tool and surface it is, as the caller
// states them (the name is read only for what the caller leaves out).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "model/io/paper_friction.hpp"
#include "model/io/paper_vibration.hpp"

namespace nibrig::model::io {

enum class PaperFormat { friction, vibration };

// The accelerometer's header (time,timestamp,xAccel,... or the blank ,,,,, of some files) or the
// force sensor's (TimeStamp,X,Y,Z). Throws FormatError naming both when it is neither.
PaperFormat paper_format_from_header(const std::filesystem::path& file);

// What the caller knows about a recording. Each given field replaces what the file name would say;
// a name that does not parse is then no error as long as everything it would have given is stated.
struct StatedRecording {
  std::optional<std::string> tool, surface;
  std::optional<double> normal_load_N, lever_factor;  // friction files only
};

// Throw FormatError naming the file and what is missing when the name does not parse and the
// statement does not make up for it, and as the readers do for bad content.
VibrationRecording read_paper_vibration(const std::filesystem::path& file,
                                        const StatedRecording& stated);
FrictionRecording read_paper_friction(const std::filesystem::path& file,
                                      const StatedRecording& stated);

}  // namespace nibrig::model::io
