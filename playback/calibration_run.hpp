// Calibrating an actuator on the real device: play the sweep through the actuator's output
// channel, record the accelerometer's input channel in the same stream (so both share one clock),
// estimate the chain's response and design its inverse filter for the engine's internal rate.
#pragma once

#include <chrono>
#include <string>

#include "playback/actuator_file.hpp"
#include "playback/audio_output.hpp"

namespace nibrig::playback {

struct CalibrationRunSettings {
  std::string name;       // the actuator's name, stored in the file
  OutputSettings device;  // output_channel = the actuator, input_channel = the accelerometer
  // The accelerometer input's scale: m/s² per unit of input level (from its datasheet and the
  // interface's input gain).
  double accelerometer_m_s2_per_unit = 1.0;
  SineSweepSettings sweep;       // its sample rate is replaced by the device's
  InverseFilterSettings design;  // rate and taps are set from the engine's internal rate
  // Silence before the sweep: the stream settles (and a JACK graph can be wired) first.
  std::chrono::milliseconds lead_in{500};
  std::chrono::seconds timeout{60};
  // Measured again, up to `attempts` times in all, while the repetitions agree to less than
  // min_snr_db (median over 20-500 Hz; about 90 dB on a clean loop): a block an xrun lost or
  // delayed in one sweep shows there. The best attempt is kept.
  int attempts = 3;
  double min_snr_db = 40.0;
};

// Throws DeviceError for the device, std::invalid_argument without an input channel or for bad
// settings, std::runtime_error when the recording did not complete within the timeout (naming how
// much arrived) or the estimate fails.
ActuatorCalibration run_calibration(const CalibrationRunSettings& settings);

// The internal rate the engine runs at for a device rate (rt::EngineSettings's rule), and the
// filter design for it: the same 64 ms of taps at every rate.
InverseFilterSettings design_for_device_rate(InverseFilterSettings design, double device_rate_hz);

}  // namespace nibrig::playback
