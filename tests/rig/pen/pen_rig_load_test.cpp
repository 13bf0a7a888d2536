// The rig's force sensor as a pen calibration's scale: RigLoadReader over the real driver, libusb
// and usbfs to the emulated controller (tests/rig/usb/emulated_rig.hpp), calibrated first with a
// known weight as a lab does.
#include "rig/pen/pen_rig_load.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "rig/pen/pen_calibration.hpp"
#include "rig/pen/pen_clock.hpp"
#include "rig/usb/controller_calibration.hpp"
#include "tests/rig/usb/emulated_rig.hpp"

namespace nibrig::rig::pen {
namespace {

using namespace std::chrono_literals;
using usb::testing::EmulatedRig;
using usb::testing::EmulatedRigConfig;

// Frames carry f32 forces and the device keeps f32 counts per N: seven digits. The mean of identical
// f32 frames is the frame's value, so a part in 10⁵ is rounding.
constexpr double kRelative = 1e-5;

class RigLoad : public ::testing::Test {
 protected:
  void SetUp() override {
    device_.place_on_arm(0.0, 0.0);
    usb::UsbRigController rig;
    usb::ControllerCalibrationSteps steps;
    steps.zero = true;
    steps.normal_weight_N = 2.0;
    steps.average_s = 0.3;
    usb::calibrate_controller(rig, steps, [&](const std::string& said) {
      if (said.find("on the tip") != std::string::npos) device_.place_on_arm(2.0, 0.0);
    });
  }
  usb::testing::Testbed testbed_;
  EmulatedRig device_{testbed_.get(), EmulatedRigConfig{"NIB-LOAD", 2}};
};

TEST_F(RigLoad, ASteadyLoadIsWhatTheSensorReadsOverTheWindow) {
  RigLoadReader reader("NIB-LOAD");
  EXPECT_EQ(reader.serial(), "NIB-LOAD");
  device_.place_on_arm(1.25, 0.0);
  std::this_thread::sleep_for(700ms);
  EXPECT_NEAR(reader.load_n(pen_clock_now_s(), 0.5), 1.25, 1.25 * kRelative);
}

// The window is placed by when the frames were sampled: one that ends just before a harder press
// reads the load before it, one across the press is refused as unsteady (1.0 and 1.5 N, half each:
// an sd of 25 %).
TEST_F(RigLoad, TheWindowIsWhenTheFramesWereSampledAndAMovingLoadIsRefused) {
  RigLoadReader reader("NIB-LOAD");
  device_.place_on_arm(1.0, 0.0);
  std::this_thread::sleep_for(700ms);
  const double pressed = pen_clock_now_s();
  device_.place_on_arm(1.5, 0.0);
  std::this_thread::sleep_for(200ms);
  EXPECT_NEAR(reader.load_n(pressed - 0.02, 0.4), 1.0, 1.0 * kRelative);
  EXPECT_THROW(reader.load_n(pressed + 0.15, 0.3), PenCalibrationRefusal);
  std::this_thread::sleep_for(400ms);
  EXPECT_NEAR(reader.load_n(pen_clock_now_s(), 0.3), 1.5, 1.5 * kRelative);
}

TEST_F(RigLoad, NoPenOnTheSensorIsRefused) {
  RigLoadReader reader("NIB-LOAD");
  device_.place_on_arm(0.0, 0.0);  // the calibration's weight taken off
  std::this_thread::sleep_for(700ms);
  EXPECT_THROW(reader.load_n(pen_clock_now_s(), 0.5), PenCalibrationRefusal);
}

TEST_F(RigLoad, AnUnpluggedRigIsRefused) {
  RigLoadReader reader("NIB-LOAD");
  device_.place_on_arm(1.0, 0.0);
  std::this_thread::sleep_for(700ms);
  device_.unplug();
  std::this_thread::sleep_for(300ms);
  EXPECT_THROW(reader.load_n(pen_clock_now_s(), 0.5), PenCalibrationRefusal);
}

}  // namespace
}  // namespace nibrig::rig::pen
