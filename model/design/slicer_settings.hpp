// What a slicer reads for a printer profile: the profile's own settings with the printer's geometry
// nibrig knows added (nozzle, layer, bed, SLA mask), as PrusaSlicer's keys, and the two files that
// carry them — the config inside the 3MF and the .ini beside it that `prusa-slicer --load` takes.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "model/io/printer_profile.hpp"

namespace nibrig::model::design {

using SlicerSettings = std::vector<std::pair<std::string, std::string>>;

// True for an FDM or MSLA profile whose slicer is PrusaSlicer: the one nibrig writes settings for
// (a PolyJet's GrabCAD Print takes none from a file).
bool reads_prusa_slicer(const io::PrinterProfile& printer);

// printer_technology, the geometry (nozzle_diameter or display_*, bed_shape, max_print_height),
// layer_height, then the profile's slicer_settings. Empty when !reads_prusa_slicer.
SlicerSettings prusa_slicer_settings(const io::PrinterProfile& printer);

// "key = value" lines: a config --load reads.
std::string prusa_slicer_ini(const SlicerSettings& settings);
// "; key = value" lines: Metadata/Slic3r_PE.config inside a 3MF, as PrusaSlicer writes it.
std::string prusa_slicer_3mf_config(const SlicerSettings& settings);

// The command that slices `three_mf` with the .ini `ini` (names as given, quoted when needed):
// "prusa-slicer --load stylus.ini --export-gcode stylus.3mf" (--export-sla for MSLA).
std::string prusa_slicer_command(const io::PrinterProfile& printer, const std::filesystem::path& ini,
                                 const std::filesystem::path& three_mf);

// The settings that make the print the modelled solid, in a line for people: "FDM, 100 % infill
// (rectilinear), 2 perimeters, 0.15 mm layers, 0.4 mm nozzle, lying". Read from the settings the
// slicer gets, so that the line says what the files say.
std::string describe_print_settings(const io::PrinterProfile& printer);

}  // namespace nibrig::model::design
