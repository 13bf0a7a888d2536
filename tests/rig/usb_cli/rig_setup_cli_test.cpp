// `nibrig rig calibrate` and `rig flash` as a user types them, the `nibrig` process
// reaching this test's emulated controller through umockdev (its preload is inherited) and the
// flash going through the real avrdude to the emulated Caterina bootloader.
#include <gtest/gtest.h>

#include <string>

#include "tests/rig/usb/avr109_bootloader.hpp"
#include "tests/rig/usb/emulated_rig.hpp"
#include "tests/rig/usb/flash_fixtures.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::rig::usb {
namespace {

using testing::EmulatedRig;
using testing::EmulatedRigConfig;
using testing::Testbed;

// The emulated normal bridge's true sensitivity (emulated_rig.hpp); f32 on the wire: 7 digits.
constexpr double kCliTrueNormalCountsPerN = 1150.0;
constexpr double kCliRelative = 1e-5;

TEST(RigSetupCommands, CalibrateWritesTheDeviceAndReadsBackItsNewSerial) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{"NIB-0C11", 2});
  device.place_on_arm(0.0, 0.0);
  ASSERT_EQ(nibrig::test::run_cli({"rig", "calibrate", "--zero", "--yes"}), 0);
  device.place_on_arm(2.0, 0.0);
  ::testing::internal::CaptureStdout();
  const int code = nibrig::test::run_cli(
      {"rig", "calibrate", "--normal-weight", "2N", "--yes", "--radius", "70", "--serial", "LAB-3"});
  const std::string out = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << out;
  // 2 N through the device's first 1000 counts/N where the bridge gives 1150: 2.3 N.
  EXPECT_NE(out.find("normal channel: read 2.3000 N"), std::string::npos) << out;
  EXPECT_NE(out.find("now on the device: normal 1150 counts/N"), std::string::npos) << out;
  EXPECT_NE(out.find("track radius 70.000 mm"), std::string::npos) << out;
  EXPECT_NEAR(device.calibration().normal_counts_per_N, kCliTrueNormalCountsPerN,
              kCliTrueNormalCountsPerN * kCliRelative);
  EXPECT_NEAR(device.geometry().track_radius_m, 0.070, 1e-9);
  // The identity read back after the rename. (`rig devices` prints the same through describe(),
  // tested in usb_rig_version_1_1_test.cpp; run here, its audio probe opens more device nodes than
  // umockdev's preload tracks, and it aborts.)
  EXPECT_NE(out.find("rig controller LAB-3 (protocol 1.2, firmware emulated-1.2)"), std::string::npos) << out;
}

TEST(RigSetupCommands, FlashAfterAResetWritesTheHexAndFindsTheControllerBack) {
  const auto hex = nibrig::test::scratch_dir("rig_flash_cli") / "nibrig-rig.hex";
  const auto image = testing::flash_test_image(300);
  testing::write_intel_hex(hex, image);
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{"NIB-0C12", 2});
  testing::add_usb_serial_port(testbed.get(), "1-6", "ttyACM1", 0x2341, 0x0037);  // a Micro, reset pressed
  testing::Avr109Bootloader bootloader(umockdev_testbed_get_dev_fd(testbed.get(), "/dev/ttyACM1"));
  ::testing::internal::CaptureStdout();
  const int code = nibrig::test::run_cli({"rig", "flash", "--port", "/dev/ttyACM1", "--hex", hex.string()});
  const std::string out = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(out.find("through /dev/ttyACM1 (2341:0037 Arduino Micro) with avrdude"), std::string::npos) << out;
  EXPECT_NE(out.find("the rig controller is back: NIB-0C12 (bus 1, address 2, protocol 1.2"), std::string::npos)
      << out;
  EXPECT_TRUE(bootloader.exited());
  const auto flash = bootloader.flash();
  for (std::size_t a = 0; a < image.size(); ++a) ASSERT_EQ(flash[a], image[a]) << "at " << a;
}

}  // namespace
}  // namespace nibrig::rig::usb
