// The rate the modal tests step at (the audio output's, 48 kHz), π and the double's epsilon,
// shared by the suites that compare a step with its closed form.
#pragma once

#include <limits>
#include <numbers>

namespace nibrig::model::modal::test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kRate = 48000.0;
inline constexpr double kEps = std::numeric_limits<double>::epsilon();

}  // namespace nibrig::model::modal::test
