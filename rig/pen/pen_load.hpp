// The load a pen calibration is told it holds, as typed: "200g", "0.2 kg", "1.5N", "1500 mN". A
// kitchen scale shows grams, the rig's force sensor newtons; a bare number is refused, as grams and
// newtons differ tenfold. (ui/options checks plain numbers only, and the rig cannot use a face's.)
#pragma once

#include <string>

namespace nibrig::rig::pen {

// A scale's mass reading as a force: standard gravity, the g a kitchen scale is calibrated for.
inline constexpr double kStandardGravity = 9.80665;

// Newtons. Throws std::invalid_argument quoting the text and saying what was expected: a decimal
// number above 0 followed by g, kg, N or mN (spaces allowed between), at most the heaviest load a
// pen takes (kMaxPenForceN, pen_force.hpp).
double parse_pen_load(const std::string& text);

}  // namespace nibrig::rig::pen
