// What `export` and `design --export` say after writing a stylus: its regions (material,
// triangles, volume), the printer's settings and the files with the print sheet; and the
// --printer option both take.
#pragma once

#include <optional>
#include <string>

#include "model/io/printer_profile.hpp"

#include "model/design/stylus_export.hpp"
#include "ui/figures/stylus_sheet.hpp"

namespace nibrig::ui::cli {

// --printer NAME|FILE: none when empty; a profile that cannot be found or read is a usage error
// naming the option.
std::optional<model::io::PrinterProfile> printer_option(const std::string& name_or_file);

// The help text of --printer, listing the bundled profiles.
std::string printer_option_help();

void print_stylus_files(const model::design::StylusPrint& print, const figures::ExportedStylus& exported);

}  // namespace nibrig::ui::cli
