// A printed part's dimensioned drawing as SVG: its top and front views drawn from the very boxes
// and holes the part is made of (so a drawing cannot drift from the geometry), its overall sizes,
// its key dimensions as text, its print settings and hardware.
#pragma once

#include <string>

#include "rig/printed_parts.hpp"

namespace nibrig::rig {

// The SVG document (millimetres on paper at 1:1 up to a page's width, smaller for larger parts).
std::string part_drawing_svg(const PrintedPart& part);

}  // namespace nibrig::rig
