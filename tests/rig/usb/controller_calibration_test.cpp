// `nibrig rig calibrate`'s library call end to end: the real driver, libusb and usbfs to the
// emulated controller, whose force sensors (emulated_rig.hpp) have counts per newton and offsets
// the device does not know until the weights teach it.
#include "rig/usb/controller_calibration.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "rig/usb/usb_rig_error.hpp"
#include "tests/rig/usb/emulated_rig.hpp"

namespace nibrig::rig::usb {
namespace {

using testing::EmulatedRig;
using testing::EmulatedRigConfig;
using testing::Testbed;

// The emulated bridges' true sensitivities (emulated_rig.hpp) and the device's first calibration.
constexpr double kBenchNormalCountsPerN = 1150.0;
constexpr double kBenchTangentialCountsPerN = 880.0;
constexpr double kBenchStartCountsPerN = 1000.0;
// Frames carry f32 forces and the device keeps f32 counts per N: seven digits. The mean of a second
// of identical f32 frames is the frame's value, so a part in 10⁵ is rounding, not noise.
constexpr double kBenchRelative = 1e-5;

// The person at the rig, played by the test: each prompt is answered by moving the weights as it
// says, in the order calibrate_controller asks.
struct BenchHands {
  EmulatedRig& device;
  std::vector<std::string> said;
  double normal_weight_N = 0.0;
  double tangential_weight_N = 0.0;
  void operator()(const std::string& instruction) {
    said.push_back(instruction);
    if (instruction.find("Lift the tip") != std::string::npos) device.place_on_arm(0.0, 0.0);
    if (instruction.find("on the tip") != std::string::npos) device.place_on_arm(normal_weight_N, 0.0);
    if (instruction.find("over the pulley") != std::string::npos) device.place_on_arm(0.0, tangential_weight_N);
  }
};

TEST(ControllerCalibration, KnownWeightsMakeTheFramesReadWhatLiesOnTheTip) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  device.place_on_arm(0.4, 0.0);  // an arm resting on the surface: zeroing must lift it
  UsbRigController rig;
  BenchHands hands{device, {}, 2.0, 0.5};
  ControllerCalibrationSteps steps;
  steps.zero = true;
  steps.normal_weight_N = 2.0;
  steps.tangential_weight_N = 0.5;
  const auto result = calibrate_controller(rig, steps, [&](const std::string& s) { hands(s); });

  ASSERT_EQ(hands.said.size(), 3u);
  EXPECT_NE(hands.said[1].find("Put the 2 N weight on the tip"), std::string::npos) << hands.said[1];
  EXPECT_EQ(result.before.normal_counts_per_N, kBenchStartCountsPerN);
  // Before: 2 N read through the wrong 1000 counts/N: 2 × 1150 / 1000 = 2.3 N.
  ASSERT_TRUE(result.normal);
  EXPECT_NEAR(result.normal->mean_N, 2.3, 2.3 * kBenchRelative);
  EXPECT_GT(result.normal->frames, 500u);  // ~1 s at 1 kHz; half allows a loaded machine
  ASSERT_TRUE(result.tangential);
  EXPECT_NEAR(result.tangential->mean_N, 0.5 * 0.88, 0.44 * kBenchRelative);
  // After: the bridges' true sensitivities, read back from the device; the lever kept.
  EXPECT_NEAR(result.after.normal_counts_per_N, kBenchNormalCountsPerN, kBenchNormalCountsPerN * kBenchRelative);
  EXPECT_NEAR(result.after.tangential_counts_per_N, kBenchTangentialCountsPerN,
              kBenchTangentialCountsPerN * kBenchRelative);
  EXPECT_EQ(result.after.lever_factor, 1.0);
  EXPECT_EQ(device.calibration().normal_counts_per_N, result.after.normal_counts_per_N);

  // And the frames now read the weights placed: a 1.5 N weight, which the calibration never saw.
  device.place_on_arm(1.5, 0.0);
  const ForceReading normal = average_force(rig, ForceChannel::kNormal, 0.3, 0.05);
  EXPECT_NEAR(normal.mean_N, 1.5, 1.5 * kBenchRelative);
  device.place_on_arm(0.0, 0.7);
  const ForceReading tangential = average_force(rig, ForceChannel::kTangential, 0.3, 0.05);
  EXPECT_NEAR(tangential.mean_N, 0.7, 0.7 * kBenchRelative);
}

TEST(ControllerCalibration, TheLeverIsKeptAndTheCountsPerNewtonTakeTheRest) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  device.place_on_arm(0.0, 0.0);
  UsbRigController rig;
  BenchHands hands{device, {}, 1.0, 0.0};
  ControllerCalibrationSteps steps;
  steps.lever_factor = 2.0;  // the tip is twice as far from the pivot as the sensor
  steps.zero = true;
  steps.normal_weight_N = 1.0;
  const auto result = calibrate_controller(rig, steps, [&](const std::string& s) { hands(s); });
  // Reported with the lever: 1 N × 1150 / 1000 × 2 = 2.3 N; counts per N = 1000 × 2.3 / 1 = 2300.
  EXPECT_NEAR(result.normal->mean_N, 2.3, 2.3 * kBenchRelative);
  EXPECT_EQ(result.after.lever_factor, 2.0);
  EXPECT_NEAR(result.after.normal_counts_per_N, 2300.0, 2300.0 * kBenchRelative);
  EXPECT_EQ(result.after.tangential_counts_per_N, kBenchStartCountsPerN);  // not asked for
}

TEST(ControllerCalibration, GeometryAndSerialAreWrittenAndReadBack) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  ControllerCalibrationSteps steps;
  steps.track_radius_m = 0.0725;
  steps.serial = "LAB-12";
  unsigned prompts = 0;
  const auto result = calibrate_controller(rig, steps, [&](const std::string&) { ++prompts; });
  EXPECT_EQ(prompts, 0u);  // nothing needs hands
  ASSERT_TRUE(result.geometry);
  EXPECT_NEAR(result.geometry->track_radius_m, 0.0725, 1e-9);  // f32 mm on the wire
  EXPECT_EQ(result.geometry->counts_per_revolution, 4480.0);   // kept: only the radius was given
  EXPECT_EQ(result.identity.serial, "LAB-12");
  EXPECT_NEAR(device.geometry().track_radius_m, 0.0725, 1e-9);
}

TEST(ControllerCalibration, AWeightThatIsNotThereIsRefusedAndNothingIsWritten) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  device.place_on_arm(0.0, 0.0);
  UsbRigController rig;
  ControllerCalibrationSteps steps;
  steps.zero = true;
  steps.normal_weight_N = 2.0;
  std::string message;
  try {
    calibrate_controller(rig, steps, [](const std::string&) {});  // nobody puts the weight on
  } catch (const UsbRigError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("the normal channel reads 0 N with 2 N on it"), std::string::npos) << message;
  EXPECT_EQ(device.calibration().normal_counts_per_N, kBenchStartCountsPerN);
}

TEST(ControllerCalibration, WeightsAreGivenInGramsKilogramsOrNewtons) {
  EXPECT_NEAR(parse_weight_N("200g", "--normal-weight"), 0.2 * 9.80665, 1e-12);
  EXPECT_NEAR(parse_weight_N("0.2 kg", "--normal-weight"), 0.2 * 9.80665, 1e-12);
  EXPECT_EQ(parse_weight_N("1.96N", "--normal-weight"), 1.96);
  try {
    parse_weight_N("200", "--normal-weight");
    FAIL() << "a bare number was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "--normal-weight '200': expected a weight above 0 with its unit, in grams, kilograms or "
              "newtons (\"200g\", \"0.2kg\", \"1.96N\")");
  }
  EXPECT_THROW(parse_weight_N("-5g", "--tangential-weight"), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::rig::usb
