// Synthetic tablet reports along an analytic path, as a tablet gives them: at its report rate, each
// stamp jittered (uniformly, by ± jitter_s), each position sampled at the true instant and rounded
// to the tablet's resolution. The path's exact speed stays with each report, for the tests to
// compare against.
#pragma once

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "rig/pen/pen_sample.hpp"

namespace nibrig::rig::pen::testing {

struct PathPoint {
  double x_m, y_m, speed_m_s;
};
// Position and exact speed at time t (s from the stroke's start).
using Path = std::function<PathPoint(double t)>;

struct SyntheticReport {
  PenSample sample;
  double true_time_s;  // the instant the position was taken
  double true_speed_m_s;
};

struct TabletModel {
  double rate_hz = 133.0;
  double jitter_s = 0.5e-3;    // stamps spread uniformly over ± this
  double resolution_m = 1e-5;  // 0.01 mm: a Wacom Intuos's 100 lines per mm
  unsigned seed = 32;
};

// The worst a single estimate can be off, from the tablet's imperfections alone: each position is
// rounded by up to half the resolution per axis (√2·r/2 in the plane), twice per difference; the
// two stamps move the 2T between them by up to ±2·jitter; on a circle the chord is shorter than
// the arc by the factor `chord`.
struct PenSpeedBounds {
  double low, high;
};
inline PenSpeedBounds pen_speed_bounds(double speed, const TabletModel& tablet, double chord = 1.0) {
  const double span = 2.0 / tablet.rate_hz;
  const double position = 2.0 * std::sqrt(2.0) * tablet.resolution_m / 2.0;
  return {(chord * speed * span - position) / (span + 2.0 * tablet.jitter_s),
          (speed * span + position) / (span - 2.0 * tablet.jitter_s)};
}

inline double quantise_to(double value, double step) { return std::round(value / step) * step; }

inline std::vector<SyntheticReport> synthetic_stroke(const Path& path, double duration_s,
                                                     const TabletModel& tablet,
                                                     double start_s = 100.0,
                                                     double pressure = 0.4) {
  std::mt19937 random(tablet.seed);
  std::uniform_real_distribution<double> jitter(-tablet.jitter_s, tablet.jitter_s);
  std::vector<SyntheticReport> reports;
  const double period = 1.0 / tablet.rate_hz;
  for (int k = 0; k * period <= duration_s + 1e-12; ++k) {
    const double t = k * period;
    const PathPoint p = path(t);
    SyntheticReport r;
    r.true_time_s = start_s + t;
    r.true_speed_m_s = p.speed_m_s;
    r.sample.time_s = start_s + t + (tablet.jitter_s > 0 ? jitter(random) : 0.0);
    r.sample.x_m = quantise_to(p.x_m, tablet.resolution_m);
    r.sample.y_m = quantise_to(p.y_m, tablet.resolution_m);
    r.sample.pressure = pressure;
    r.sample.tip_down = true;
    r.sample.in_proximity = true;
    reports.push_back(r);
  }
  return reports;
}

// A straight line at a constant speed, at an angle so that both axes are rounded.
inline Path straight_line(double speed_m_s, double angle_rad = 0.5) {
  return [speed_m_s, angle_rad](double t) {
    return PathPoint{0.05 + speed_m_s * t * std::cos(angle_rad),
                     0.04 + speed_m_s * t * std::sin(angle_rad), speed_m_s};
  };
}

// A circle of radius r at a constant speed.
inline Path circle(double speed_m_s, double radius_m) {
  return [speed_m_s, radius_m](double t) {
    const double angle = speed_m_s / radius_m * t;
    return PathPoint{0.08 + radius_m * std::cos(angle), 0.06 + radius_m * std::sin(angle),
                     speed_m_s};
  };
}

// A line whose speed grows steadily: v(t) = v0 + a t.
inline Path accelerating_line(double v0_m_s, double a_m_s2) {
  return [v0_m_s, a_m_s2](double t) {
    const double s = v0_m_s * t + 0.5 * a_m_s2 * t * t;
    return PathPoint{0.03 + 0.8 * s, 0.02 + 0.6 * s, v0_m_s + a_m_s2 * t};
  };
}

}  // namespace nibrig::rig::pen::testing
