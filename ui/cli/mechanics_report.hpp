// File names for the mechanics commands' outputs; the mode report itself is
// model/mechanics/mode_report.hpp.
#pragma once

#include <string>

namespace nibrig::ui::cli {

// Letters and digits kept, everything else '_': "VeroClear stylus, 1 mm" ->
// "VeroClear_stylus__1_mm".
std::string file_stem(const std::string& name);

}  // namespace nibrig::ui::cli
