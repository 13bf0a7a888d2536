// What `export` and `design --export` say after writing a stylus: its regions (material,
// triangles, volume) and the files.
#pragma once

#include "model/design/stylus_export.hpp"

namespace nibrig::ui::cli {

void print_stylus_files(const model::design::StylusPrint& print, const model::design::StylusFiles& files);

}  // namespace nibrig::ui::cli
