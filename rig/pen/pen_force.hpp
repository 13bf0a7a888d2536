// A pen's pressure curve: libinput's normalised pressure (0 … 1) to the normal force on the tip in
// newtons, the force the engine's live contact takes. Measured per pen (pen_calibration.hpp),
// stored by name (pen_force_file.hpp), or the documented default below when a pen has none.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace nibrig::rig::pen {

struct PressurePoint {
  double pressure = 0.0;  // libinput's normalised pressure, 0 … 1
  double force_n = 0.0;
};

// The heaviest load a point may hold: no pen tip bears more (a tablet pen saturates near 5 N).
inline constexpr double kMaxPenForceN = 50.0;

// What is wrong with a curve's points, or "" when nothing is; `index` is then the offending point.
// A curve has at least two points, pressures in [0, 1] rising strictly, forces in [0,
// kMaxPenForceN] rising strictly, the first at 0 N (the pressure where the tip starts to bear
// load).
std::string pressure_points_problem(const std::vector<PressurePoint>& points, std::size_t& index);

class PressureCurve {
 public:
  // Throws std::invalid_argument naming the point and the problem (pressure_points_problem).
  explicit PressureCurve(std::vector<PressurePoint> points);

  // Piecewise linear through the points; 0 N at or below the first point's pressure; above the
  // last point the last segment goes on. A kitchen scale rarely reaches a pen's full pressure, and
  // the last segment's slope is the best measure there is of the rest, where holding the last
  // force would flatten the pen's top; libinput's pressure stops at 1, which bounds it. A pressure
  // that is not finite gives 0 N.
  double force_n(double pressure) const noexcept;

  const std::vector<PressurePoint>& points() const noexcept { return points_; }

 private:
  std::vector<PressurePoint> points_;
};

// The default curve, for a pen with no calibration: straight from 0 N at pressure 0 to
// kDefaultFullScaleN at pressure 1. Wacom states its pens' pressure levels but not the force they
// span; Huion states the range of its PW600 pens as 2 g (initial activation force) to 500 g
// (maximum), and XP-Pen its X3 Pro's as 3 g to 400 g. The default takes the 500 g maximum
// (4.90 N). libinput's pressure 0 is the tip's contact threshold, so the few grams of activation
// force are at pressure 0. Straight because the shape differs from pen to pen (an EMR pen's
// pressure usually rises fastest at light loads) and is only known by measuring.
inline constexpr double kDefaultFullScaleN = 0.500 * 9.80665;
const PressureCurve& default_pressure_curve();

}  // namespace nibrig::rig::pen
