// The stroke a person plays tools with: one setting for the whole panel (the space and design views
// edit it, the status line shows it, every view plays it, and it is remembered between runs).
#pragma once

#include <string>

#include "rt/reference_load.hpp"
#include "rt/stroke_request.hpp"

namespace nibrig::ui::panel {

struct StrokeChoice {
  int kind = 1;  // 0 constant speed, 1 the rig's sweep, 2 an artist's trajectory
  float speed_mm_s = 100.0f;
  float force_n = static_cast<float>(rt::kReferenceNormalForce);
  std::string trajectory;
  rt::StrokeRequest request() const;
  bool operator==(const StrokeChoice&) const = default;
};

// Its widgets; true when it changed.
bool stroke_widgets(StrokeChoice& choice);

}  // namespace nibrig::ui::panel
