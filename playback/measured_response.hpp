// A complex frequency response sampled at a list of frequencies: what a calibration sweep measures
// and what the inverse filter is designed from. Units are the caller's (for the actuator chain:
// m/s² at the accelerometer per unit of output level, full scale = 1).
#pragma once

#include <complex>
#include <vector>

namespace nibrig::playback {

struct FrequencyResponse {
  std::vector<double> frequencies_hz;  // strictly increasing, positive
  std::vector<std::complex<double>> values;
};

}  // namespace nibrig::playback
