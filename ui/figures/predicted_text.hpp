// A predicted design's descriptors in a line, as `nibrig predict`, the demo and a stylus's print
// sheet show them.
#pragma once

#include <string>

#include "model/design/predicted_tool.hpp"

namespace nibrig::ui::figures {

// "mu 0.273 ± 0.0087, weighted mean vibration 0.07339 ± 12.8 %": the predicted descriptors with
// their cross-validated error (± one standard deviation; none printed when the tool has none, a
// measured μ having no interpolation error).
std::string describe_descriptors(const model::design::PredictedTool& tool);

}  // namespace nibrig::ui::figures
