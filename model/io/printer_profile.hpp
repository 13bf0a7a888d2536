// A printer profile (FORMATS.md "Printer profile"): the process a lab's printer uses, the materials
// it has, whether it mixes them, and the settings that make its print the solid nibrig modelled,
// each value with its source. Bundled ones live in assets/printers/, a lab's own by name in the
// user store; `find_printer_profile` takes a name or a file.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace nibrig::model::io {

enum class PrintProcess { fdm, msla, polyjet };

// "FDM", "MSLA", "PolyJet": how the sheet and messages name it.
std::string process_name(PrintProcess process);

struct PrinterProfile {
  std::string name;     // what --printer takes: "prusa-mk3s"
  std::string printer;  // the machine, for people: "Original Prusa i3 MK3S & MK3S+, 0.4 mm nozzle"
  PrintProcess process = PrintProcess::fdm;
  std::vector<std::string> materials;  // names in the material table it can print
  bool mixes_materials = false;        // PolyJet digital materials: fractions dithered in one region
  int materials_per_print = 1;         // distinct materials one print may hold (regions of the part)
  std::array<double, 3> build_volume_m{};
  std::string orientation;         // "lying" (axis along x on the bed) or "standing" (axis along z)
  std::string orientation_reason;  // why, in a sentence
  std::string supports;            // how the part is supported, in words
  double layer_height_m = 0.0;
  double nozzle_diameter_m = 0.0;           // FDM
  std::array<double, 2> display_m{};        // MSLA: the mask's width and height
  std::array<int, 2> display_pixels{};      // MSLA
  int min_feature_pixels = 0;               // MSLA: the narrowest tip it is trusted with, in pixels
  double xy_resolution_m = 0.0;             // PolyJet: the head's dot pitch
  std::string post_process;                 // post-cure, support removal: in words
  std::string slicer;                       // what reads the settings: "PrusaSlicer 2.5", "GrabCAD Print"
  // The slicer's own settings (PrusaSlicer's keys and value text), sorted by key; nibrig adds the
  // printer's geometry (prusa_slicer_settings in model/design/slicer_settings.hpp).
  std::vector<std::pair<std::string, std::string>> slicer_settings;
  // Each setting's source by its field name ("layer_height_mm", "slicer_settings.perimeters").
  std::vector<std::pair<std::string, std::string>> sources;
  std::filesystem::path file;  // where it was read from

  // The XY pixel of an MSLA printer (display width / pixels), 0 for another process.
  double pixel_size_m() const;
  // The slicer setting `key`, or "" when the profile does not set it.
  std::string slicer_setting(const std::string& key) const;
  // The source of field `key`, or "".
  std::string source_of(const std::string& key) const;
};

// Format "nibrig-printer", version 1. Throws FormatError naming the file and field: a process other
// than fdm, msla or polyjet; a value out of its range; a number or slicer setting without its source
// in `sources`; an FDM profile whose slicer settings would not print a solid part (fill_density not
// "100%", or a fill_pattern PrusaSlicer cannot fill at 100 %, which it silently prints at 20 %).
PrinterProfile read_printer_profile(const std::filesystem::path& file);

// The folder of a lab's own profiles: $NIBRIG_PRINTERS, else $XDG_DATA_HOME/nibrig/printers, else
// ~/.local/share/nibrig/printers.
std::filesystem::path user_printers_folder();

// The names of the bundled profiles (assets/printers/*.json), sorted.
std::vector<std::string> bundled_printer_names();

// `name_or_file`: a file that exists, else a name in the user's folder, else a bundled one. Throws
// std::invalid_argument listing the bundled and the user's names when there is none.
PrinterProfile find_printer_profile(const std::string& name_or_file);

}  // namespace nibrig::model::io
