// What `export` and `design --export` say after writing a stylus: its regions (material,
// triangles, volume) and the files with the print sheet.
#pragma once

#include "model/design/stylus_export.hpp"
#include "ui/figures/stylus_sheet.hpp"

namespace nibrig::ui::cli {

void print_stylus_files(const model::design::StylusPrint& print, const figures::ExportedStylus& exported);

}  // namespace nibrig::ui::cli
