// The per-actuator calibration file (JSON, "nibrig-actuator" version 1): the sweep's settings, the
// measured chain, and the inverse filter designed from it. Written atomically; read back with every
// field validated; the filter can be redesigned from the stored response for another engine rate.
#pragma once

#include <filesystem>
#include <string>

#include "playback/inverse_filter.hpp"
#include "playback/measured_response.hpp"
#include "playback/sine_sweep.hpp"

namespace nibrig::playback {

struct ActuatorCalibration {
  std::string name;
  std::string created;  // ISO 8601, e.g. "2025-01-31T14:05:00Z"; kept as given
  SineSweepSettings sweep;
  double delay_s = 0.0;
  // m/s² at the accelerometer per unit output, its delay taken out (phase relative to the onset).
  FrequencyResponse response;
  // The design's settings (band, regularisation, maximum boost, rate and taps) and its result.
  InverseFilterSettings design;
  InverseFilter filter;
};

// Throws std::runtime_error (naming the file) when it cannot be written; std::invalid_argument when
// the calibration is incomplete (no response, no taps).
void write_actuator_file(const std::filesystem::path& file, const ActuatorCalibration& calibration);

// Throws model::io::FormatError naming the file, the JSON path of the bad field and what was
// expected.
ActuatorCalibration read_actuator_file(const std::filesystem::path& file);

// The same design from the stored response at another internal rate, with the same filter length in
// seconds (so the same frequency resolution): the engine's rate follows the device's.
InverseFilter redesign_for_rate(const ActuatorCalibration& calibration, double sample_rate_hz);

}  // namespace nibrig::playback
