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
  const auto json = nibrig::test::scratch_dir("rig_calibrate_cli") / "calibration.json";
  const int code =
      nibrig::test::run_cli({"rig", "calibrate", "--normal-weight", "2N", "--yes", "--radius", "70",
                             "--serial", "LAB-3", "--json", json.string()});
  ASSERT_EQ(code, 0);
  const auto said = nibrig::test::read_json(json);
  // 2 N through the device's first 1000 counts/N where the bridge gives 1150: 2.3 N, averaged over
  // a second of frames whose noise is far below the relative tolerance.
  EXPECT_NEAR(said["normal"]["known_N"].get<double>(), 2.0, 1e-12) << said;
  EXPECT_NEAR(said["normal"]["read_N"].get<double>(), 2.3, 2.3 * kCliRelative) << said;
  EXPECT_GT(said["normal"]["frames"].get<int>(), 0) << said;
  EXPECT_TRUE(said["tangential"].is_null()) << said;
  EXPECT_NEAR(said["before"]["normal_counts_per_N"].get<double>(), 1000.0, 1e-9) << said;
  EXPECT_NEAR(said["after"]["normal_counts_per_N"].get<double>(), kCliTrueNormalCountsPerN,
              kCliTrueNormalCountsPerN * kCliRelative)
      << said;
  // What the command reports is what the device holds.
  EXPECT_DOUBLE_EQ(said["after"]["normal_counts_per_N"].get<double>(),
                   device.calibration().normal_counts_per_N);
  EXPECT_NEAR(device.calibration().normal_counts_per_N, kCliTrueNormalCountsPerN,
              kCliTrueNormalCountsPerN * kCliRelative);
  EXPECT_NEAR(said["geometry"]["track_radius_mm"].get<double>(), 70.0, 1e-6) << said;
  EXPECT_NEAR(device.geometry().track_radius_m, 0.070, 1e-9);
  // The identity read back after the rename. (`rig devices` prints the same through describe(),
  // tested in usb_rig_version_1_1_test.cpp; run here, its audio probe opens more device nodes than
  // umockdev's preload tracks, and it aborts.)
  EXPECT_EQ(said["controller"]["serial"], "LAB-3") << said;
  EXPECT_EQ(said["controller"]["protocol_version"], "1.2") << said;
  EXPECT_EQ(said["controller"]["firmware"], "emulated-1.2") << said;
}

TEST(RigSetupCommands, FlashAfterAResetWritesTheHexAndFindsTheControllerBack) {
  const auto hex = nibrig::test::scratch_dir("rig_flash_cli") / "nibrig-rig.hex";
  const auto image = testing::flash_test_image(300);
  testing::write_intel_hex(hex, image);
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{"NIB-0C12", 2});
  testing::add_usb_serial_port(testbed.get(), "1-6", "ttyACM1", 0x2341, 0x0037);  // a Micro, reset pressed
  testing::Avr109Bootloader bootloader(umockdev_testbed_get_dev_fd(testbed.get(), "/dev/ttyACM1"));
  const auto json = hex.parent_path() / "flashed.json";
  const int code = nibrig::test::run_cli(
      {"rig", "flash", "--port", "/dev/ttyACM1", "--hex", hex.string(), "--json", json.string()});
  ASSERT_EQ(code, 0);
  const auto said = nibrig::test::read_json(json);
  EXPECT_EQ(said["hex"], hex.string()) << said;
  EXPECT_EQ(said["port"]["device"], "/dev/ttyACM1") << said;
  EXPECT_EQ(said["port"]["usb_id"], "2341:0037") << said;
  EXPECT_EQ(said["port"]["board"], "Arduino Micro") << said;
  EXPECT_EQ(said["controller"]["serial"], "NIB-0C12") << said;
  EXPECT_EQ(said["controller"]["bus"], 1) << said;
  EXPECT_EQ(said["controller"]["address"], 2) << said;
  EXPECT_EQ(said["controller"]["protocol_version"], "1.2") << said;
  EXPECT_TRUE(said["controller"]["problem"].is_null()) << said;
  EXPECT_TRUE(bootloader.exited());
  const auto flash = bootloader.flash();
  for (std::size_t a = 0; a < image.size(); ++a) ASSERT_EQ(flash[a], image[a]) << "at " << a;
}

}  // namespace
}  // namespace nibrig::rig::usb
