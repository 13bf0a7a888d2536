#include "rig/usb/controller_calibration.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>
#include <vector>

namespace nibrig::rig::usb {
namespace {

// A reading under a hundredth of the weight means the weight is not on this channel, or the
// channel is not wired: dividing by it would make the device read nonsense.
constexpr double kCalibrationLeastReportedShare = 0.01;
// Frames that must arrive of those the frame rate promises; fewer is a stream that is not flowing.
constexpr double kCalibrationLeastFrameShare = 0.5;

std::string calibration_newtons(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g N", value);
  return text;
}

void drop_queued_frames(UsbRigController& rig) {
  std::vector<SensorFrame> block(1024);
  while (rig.read_frames(block) > 0) {
  }
}

void require_positive_step(std::optional<double> value, const char* what) {
  if (value && !(std::isfinite(*value) && *value > 0.0)) {
    throw std::invalid_argument(std::string(what) + " " + std::to_string(*value) +
                                ": expected a finite number above 0");
  }
}

// counts per N = old × reported / known (see the header for why), refused when the reading is far
// too small or of the wrong sign to be the weight.
double calibrated_counts_per_N(double old_counts_per_N, const ForceReading& reading, double known_N,
                               const char* channel) {
  if (!(reading.mean_N > kCalibrationLeastReportedShare * known_N)) {
    throw UsbRigError(std::string("the ") + channel + " channel reads " + calibration_newtons(reading.mean_N) + " with " +
                      calibration_newtons(known_N) + " on it: is the weight on the arm, the channel wired, and was it zeroed "
                      "with the tip lifted?");
  }
  return old_counts_per_N * reading.mean_N / known_N;
}

}  // namespace

double parse_weight_N(const std::string& text, const std::string& option) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  std::string unit = used > 0 ? text.substr(used) : "";
  while (!unit.empty() && unit.front() == ' ') unit.erase(unit.begin());
  double scale = 0.0;
  if (unit == "g") scale = kStandardGravity_m_s2 / 1000.0;
  if (unit == "kg") scale = kStandardGravity_m_s2;
  if (unit == "N") scale = 1.0;
  if (used == 0 || scale == 0.0 || !std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(option + " '" + text +
                                "': expected a weight above 0 with its unit, in grams, kilograms or newtons "
                                "(\"200g\", \"0.2kg\", \"1.96N\")");
  }
  return value * scale;
}

ForceReading average_force(UsbRigController& rig, ForceChannel channel, double seconds, double settle_s) {
  using clock = std::chrono::steady_clock;
  drop_queued_frames(rig);
  std::this_thread::sleep_for(std::chrono::duration<double>(settle_s));
  drop_queued_frames(rig);
  const bool normal = channel == ForceChannel::kNormal;
  const char* name = normal ? "normal" : "tangential";
  const std::uint16_t saturated = normal ? kNormalForceSaturated : kTangentialForceSaturated;
  std::vector<SensorFrame> block(1024);
  double sum = 0.0, sum_sq = 0.0;
  std::size_t count = 0;
  const auto end = clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(seconds));
  while (clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const std::size_t n = rig.read_frames(block);
    for (std::size_t i = 0; i < n; ++i) {
      if ((block[i].flags & saturated) != 0) {
        throw UsbRigError(std::string("the ") + name + " channel is saturated (frame " +
                          std::to_string(block[i].sequence) + "): the weight is beyond the sensor's range");
      }
      const double f = normal ? block[i].normal_force_N : block[i].tangential_force_N;
      sum += f;
      sum_sq += f * f;
      ++count;
    }
  }
  const double expected = rig.identity().frame_rate_hz * seconds;
  if (count < kCalibrationLeastFrameShare * expected || count == 0) {
    throw UsbRigError("only " + std::to_string(count) + " frames arrived in " + std::to_string(seconds) +
                      " s (the rig controller samples " + std::to_string(rig.identity().frame_rate_hz) +
                      " a second): the " + name + " force cannot be averaged");
  }
  ForceReading r;
  r.frames = count;
  r.mean_N = sum / static_cast<double>(count);
  r.std_dev_N = std::sqrt(std::max(0.0, sum_sq / static_cast<double>(count) - r.mean_N * r.mean_N));
  return r;
}

ControllerCalibrationResult calibrate_controller(UsbRigController& rig, const ControllerCalibrationSteps& steps,
                                                 const CalibrationPrompt& prompt) {
  require_positive_step(steps.lever_factor, "lever factor");
  require_positive_step(steps.normal_weight_N, "normal weight (N)");
  require_positive_step(steps.tangential_weight_N, "tangential weight (N)");
  require_positive_step(steps.track_radius_m, "track radius (m)");
  require_positive_step(steps.counts_per_revolution, "counts per revolution");
  if (steps.serial) {
    if (const std::string problem = serial_problem(*steps.serial); !problem.empty()) {
      throw std::invalid_argument("serial: " + problem);
    }
  }
  ControllerCalibrationResult result;
  result.before = rig.calibration();
  ForceCalibration calibration = result.before;
  // The lever first: the weights' readings are tip forces through it.
  if (steps.lever_factor) {
    calibration.lever_factor = *steps.lever_factor;
    rig.set_calibration(calibration);
  }
  if (steps.zero) {
    prompt("Lift the tip off the surface and take every weight off the arm");
    rig.zero_force();
    // The device averages up to 100 ms for its zero (PROTOCOL.md): nothing goes on the arm before
    // that is over, or the weight is zeroed away.
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
  }
  if (steps.normal_weight_N) {
    prompt("Put the " + calibration_newtons(*steps.normal_weight_N) + " weight on the tip, pressing straight down");
    result.normal = average_force(rig, ForceChannel::kNormal, steps.average_s, steps.settle_s);
    calibration.normal_counts_per_N =
        calibrated_counts_per_N(calibration.normal_counts_per_N, *result.normal, *steps.normal_weight_N, "normal");
    rig.set_calibration(calibration);
  }
  if (steps.tangential_weight_N) {
    prompt("Hang the " + calibration_newtons(*steps.tangential_weight_N) +
           " weight over the pulley, pulling the tip along the track, with nothing pressing down");
    result.tangential = average_force(rig, ForceChannel::kTangential, steps.average_s, steps.settle_s);
    calibration.tangential_counts_per_N = calibrated_counts_per_N(
        calibration.tangential_counts_per_N, *result.tangential, *steps.tangential_weight_N, "tangential");
    rig.set_calibration(calibration);
  }
  if (steps.track_radius_m || steps.counts_per_revolution) {
    Geometry geometry = rig.geometry();
    if (steps.track_radius_m) geometry.track_radius_m = *steps.track_radius_m;
    if (steps.counts_per_revolution) geometry.counts_per_revolution = *steps.counts_per_revolution;
    rig.set_geometry(geometry);
  }
  if (steps.serial) rig.set_serial(*steps.serial);

  result.after = rig.calibration();
  result.identity = rig.identify();
  if (result.identity.protocol_version >= kGeometryVersion) result.geometry = rig.geometry();
  return result;
}

}  // namespace nibrig::rig::usb
