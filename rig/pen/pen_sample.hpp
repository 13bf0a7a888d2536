// What a pen tablet reports, once libinput has read it: one tablet-tool event in SI units on the
// kernel's clock, the unit every other part of the pen path (speed, force, strokes, recording)
// takes. Positions are from the tablet's top-left corner, as the tablet reports them.
#pragma once

#include <cstdint>

namespace nibrig::rig::pen {

struct PenSample {
  double time_s = 0.0;  // the kernel's stamp, CLOCK_MONOTONIC
  double x_m = 0.0, y_m = 0.0;
  double pressure = 0.0;  // libinput's normalised pressure, 0 … 1 over the tool's range
  double tilt_x_deg = 0.0, tilt_y_deg = 0.0;
  bool tip_down = false;      // the tip touches the tablet
  bool in_proximity = false;  // the pen is within the tablet's reach
};

}  // namespace nibrig::rig::pen
