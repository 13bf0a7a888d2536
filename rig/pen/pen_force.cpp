#include "rig/pen/pen_force.hpp"

#include <cmath>
#include <stdexcept>

namespace nibrig::rig::pen {

std::string pressure_points_problem(const std::vector<PressurePoint>& points, std::size_t& index) {
  index = 0;
  if (points.size() < 2)
    return "expected at least two points, found " + std::to_string(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    index = i;
    const PressurePoint& p = points[i];
    if (!std::isfinite(p.pressure) || p.pressure < 0.0 || p.pressure > 1.0)
      return "expected a pressure from 0 to 1 (libinput's normalised pressure)";
    if (!std::isfinite(p.force_n) || p.force_n < 0.0 || p.force_n > kMaxPenForceN)
      return "expected a force from 0 to " + std::to_string(static_cast<int>(kMaxPenForceN)) +
             " N (no pen tip bears more)";
    if (i == 0 && p.force_n != 0.0)
      return "expected the first point at 0 N: the pressure where the tip starts to bear load";
    if (i > 0 && !(p.pressure > points[i - 1].pressure))
      return "expected pressures rising from point to point";
    if (i > 0 && !(p.force_n > points[i - 1].force_n))
      return "expected forces rising from point to point";
  }
  return "";
}

PressureCurve::PressureCurve(std::vector<PressurePoint> points) : points_(std::move(points)) {
  std::size_t index = 0;
  const std::string problem = pressure_points_problem(points_, index);
  if (!problem.empty())
    throw std::invalid_argument("pressure curve, point " + std::to_string(index) + ": " + problem);
}

double PressureCurve::force_n(double pressure) const noexcept {
  if (!std::isfinite(pressure) || pressure <= points_.front().pressure) return 0.0;
  std::size_t upper = 1;
  while (upper + 1 < points_.size() && pressure > points_[upper].pressure) ++upper;
  const PressurePoint& a = points_[upper - 1];
  const PressurePoint& b = points_[upper];
  return a.force_n + (pressure - a.pressure) * (b.force_n - a.force_n) / (b.pressure - a.pressure);
}

const PressureCurve& default_pressure_curve() {
  static const PressureCurve curve({{0.0, 0.0}, {1.0, kDefaultFullScaleN}});
  return curve;
}

}  // namespace nibrig::rig::pen
