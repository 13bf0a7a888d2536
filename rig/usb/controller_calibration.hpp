// Setting up a rig controller a lab has built: the force channels zeroed and calibrated with known
// weights from what the frames report, the lever factor, the turntable's geometry and the serial,
// each written to the device and read back. `nibrig rig calibrate` is this call with a terminal's
// prompts; a test drives it against the emulated controller.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "rig/usb/usb_rig_controller.hpp"

namespace nibrig::rig::usb {

// Standard gravity: what a weight in grams presses with.
inline constexpr double kStandardGravity_m_s2 = 9.80665;

// "200g", "200 g", "0.2kg" or "1.96N" in newtons. Throws std::invalid_argument naming `option`, the
// text and what was expected (a bare number is refused: grams and newtons differ a hundredfold).
double parse_weight_N(const std::string& text, const std::string& option);

struct ControllerCalibrationSteps {
  bool zero = false;                          // with the tip lifted: ZERO_FORCE
  std::optional<double> normal_weight_N;      // a known weight on the tip, pressing down
  std::optional<double> tangential_weight_N;  // a known weight pulling the tip along, over a pulley
  std::optional<double> lever_factor;         // tip force / sensor force, set as given
  std::optional<double> track_radius_m;       // SET_GEOMETRY (protocol 1.1)
  std::optional<double> counts_per_revolution;
  std::optional<std::string> serial;          // SET_SERIAL (protocol 1.1)
  double average_s = 1.0;                     // frames averaged for each weight
  double settle_s = 0.2;                      // frames ignored after each change (the device's zero takes up to 100 ms)
};

// What a person at the rig is asked to do ("lift the tip, then press Enter"); it returns when done.
// A script passes one that returns at once.
using CalibrationPrompt = std::function<void(const std::string& instruction)>;

struct ForceReading {
  double mean_N = 0.0;       // the frames' force averaged
  double std_dev_N = 0.0;    // their spread
  std::size_t frames = 0;
};

struct ControllerCalibrationResult {
  ForceCalibration before;  // read from the device first
  ForceCalibration after;   // read back at the end: what the device holds
  std::optional<ForceReading> normal, tangential;  // reported with the weights on, before the change
  std::optional<Geometry> geometry;  // read back (protocol 1.1 devices)
  Identity identity;                 // IDENTIFY at the end (the new serial)
};

// Runs the steps asked for, in this order: lever, zero, normal weight, tangential weight, geometry,
// serial. A weight's channel gets counts per N = old counts per N × reported / known: the device
// reports (counts − zero) / counts_per_N × lever, so that ratio makes it report the known weight
// with the lever kept, which stays the arm's measured geometry rather than a fitted number.
// Throws UsbRigError (the device refused, was unplugged, or a reading makes no sense) or
// std::invalid_argument (a step's value).
ControllerCalibrationResult calibrate_controller(UsbRigController& rig, const ControllerCalibrationSteps& steps,
                                                 const CalibrationPrompt& prompt);

// The frames' normal (or tangential) force averaged over `seconds`, after dropping what arrived
// before and `settle_s` more. Throws UsbRigError when too few frames arrive or a frame is saturated.
enum class ForceChannel { kNormal, kTangential };
ForceReading average_force(UsbRigController& rig, ForceChannel channel, double seconds, double settle_s);

}  // namespace nibrig::rig::usb
