// `nibrig rig calibrate`'s library call against the real firmware on the simulated board: the
// board's load cells are not the reference design's (0.30 V/N through their amplifiers, where the
// firmware's factory calibration assumes 0.255), so before the weights every force reads 15 % low
// and after them the frames read what lies on the tip. The weights, the zero and the new counts per
// newton travel the whole chain: bridge voltage, the chip's ADC, the firmware's means and EEPROM,
// USB, the host driver.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rig/usb/controller_calibration.hpp"
#include "tests/rig/usb/firmware_rig.hpp"

namespace nibrig::rig::usb::testing {
namespace {

// 0.30 V/N into 1024 counts over 5 V.
constexpr double kTrueCountsPerN = 0.30 * 1024.0 / 5.0;

TEST(FirmwareCalibration, KnownWeightsTeachTheFirmwareAnotherLoadCell) {
  Testbed testbed;
  TurntablePhysics bench;
  bench.amplifier_V_per_N = 0.30;
  FirmwareRig device(testbed.get(), EmulatedRigConfig{}, bench);
  device.place_on_arm(0.4, 0.0);  // an arm resting on the surface: zeroing must lift it
  UsbRigController rig;
  ControllerCalibrationSteps steps;
  steps.zero = true;
  steps.normal_weight_N = 2.0;
  steps.tangential_weight_N = 1.0;
  const auto result = calibrate_controller(rig, steps, [&](const std::string& instruction) {
    if (instruction.find("Lift the tip") != std::string::npos) device.place_on_arm(0.0, 0.0);
    if (instruction.find("on the tip") != std::string::npos) device.place_on_arm(2.0, 0.0);
    if (instruction.find("over the pulley") != std::string::npos) device.place_on_arm(0.0, 1.0);
  });
  // The ADC's counts are whole: 2 N is 123 counts above the zero and 1 N 61, so one count is 0.8 %
  // and 1.6 % of them; the zero, taken from steady counts, adds at most half a count.
  ASSERT_TRUE(result.normal);
  ASSERT_TRUE(result.tangential);
  EXPECT_NEAR(result.normal->mean_N, 2.0 * kTrueCountsPerN / 52.2, 0.012 * 2.0);
  EXPECT_NEAR(result.after.normal_counts_per_N, kTrueCountsPerN, 0.012 * kTrueCountsPerN);
  EXPECT_NEAR(result.after.tangential_counts_per_N, kTrueCountsPerN, 0.024 * kTrueCountsPerN);
  // Kept in the firmware's memory and in its EEPROM, from where a power cycle reads it.
  EXPECT_EQ(device.calibration().normal_counts_per_N, result.after.normal_counts_per_N);

  // And the frames read a weight the calibration never saw.
  device.place_on_arm(1.5, 0.0);
  const ForceReading normal = average_force(rig, ForceChannel::kNormal, 0.3, 0.05);
  EXPECT_NEAR(normal.mean_N, 1.5, 0.015 * 1.5 + 1.0 / kTrueCountsPerN);
}

}  // namespace
}  // namespace nibrig::rig::usb::testing
