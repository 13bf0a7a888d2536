// The Kaiser window that the interpolators (Upsampler, FrameInterpolator) taper their sincs with.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nibrig::rt {

// Kaiser's formulas for a stop band `db` down (above 50 dB): the window's β, and the length in
// samples for a transition band of `transition` (a fraction of the sample rate).
constexpr double kaiser_beta(double db) { return 0.1102 * (db - 8.7); }
inline double kaiser_length(double db, double transition) {
  return (db - 7.95) / (2.285 * 2 * std::numbers::pi * transition);
}

// The window at u, in half-lengths from its centre (0 beyond ±1).
inline double kaiser_window(double u, double beta) {
  return std::cyl_bessel_i(0.0, beta * std::sqrt(std::max(0.0, 1.0 - u * u))) /
         std::cyl_bessel_i(0.0, beta);
}

}  // namespace nibrig::rt
