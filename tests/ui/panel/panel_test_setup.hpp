// What the panel's window tests set up alike: a hidden window that renders as fast as it can, and
// the design view's coarse grid (3 × 3 designs on a 4 mm mesh with 32 modes: solved in seconds,
// where the default grid takes half a minute the first time).
#pragma once

#include "ui/panel/design_view.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel::testing {

inline WindowSettings hidden_window() {
  WindowSettings w;
  w.visible = false;
  w.vsync = false;
  return w;
}

inline DesignSettings coarse_design(std::size_t error_points = 2) {
  DesignSettings d;
  d.fraction_points = 3;
  d.tip_points = 3;
  d.mesh_size_m = 0.004;
  d.modes = 32;
  d.error_points = error_points;
  return d;
}

}  // namespace nibrig::ui::panel::testing
