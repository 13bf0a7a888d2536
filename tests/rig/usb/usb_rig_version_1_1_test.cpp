// Protocol 1.1's requests (geometry, serial, bootloader) through the real driver and libusb to the
// emulated controller, and what a 1.0 device answers instead.
#include <gtest/gtest.h>

#include <string>

#include "rig/usb/usb_device_list.hpp"
#include "rig/usb/usb_rig_controller.hpp"
#include "rig/usb/usb_rig_error.hpp"
#include "tests/rig/usb/emulated_rig.hpp"

namespace nibrig::rig::usb {
namespace {

using testing::EmulatedRig;
using testing::EmulatedRigConfig;
using testing::Testbed;

template <typename F>
std::string version_1_1_error_of(F f) {
  try {
    f();
  } catch (const UsbRigError& e) {
    return e.what();
  }
  return "";
}

TEST(UsbRigVersion11, GeometryBytesMatchTheDocumentedLayout) {
  const auto bytes = encode_geometry({4480.0, 0.060});
  // f32 4480 = 0x458C0000, f32 60 = 0x42700000, little-endian.
  const std::array<std::uint8_t, 8> expected = {0x00, 0x00, 0x8C, 0x45, 0x00, 0x00, 0x70, 0x42};
  EXPECT_EQ(bytes, expected);
  const Geometry back = decode_geometry(bytes);
  EXPECT_EQ(back.counts_per_revolution, 4480.0);
  EXPECT_NEAR(back.track_radius_m, 0.060, 1e-9);  // 60 mm is exact in f32; the division is not
}

TEST(UsbRigVersion11, ASerialIsPrintableAsciiWithoutSpaces) {
  EXPECT_EQ(serial_problem("LAB-7"), "");
  EXPECT_EQ(serial_problem(""), "a serial cannot be empty");
  EXPECT_EQ(serial_problem("LAB 7"),
            "character 4 of the serial is byte 0x20; a serial is printable ASCII without spaces (0x21..0x7E)");
  EXPECT_NE(serial_problem("ABCDEFGHIJKLMNOPQ").find("at most 16"), std::string::npos);
  const auto bytes = encode_serial("LAB-7");
  EXPECT_EQ(decode_serial(bytes), "LAB-7");
  EXPECT_EQ(bytes[5], 0);
  EXPECT_EQ(bytes[15], 0);
}

TEST(UsbRigVersion11, GeometryIsWrittenAndReadBack) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  EXPECT_EQ(rig.identify().protocol_version, kProtocolVersion);
  const Geometry fresh = rig.geometry();
  EXPECT_EQ(fresh.counts_per_revolution, 4480.0);
  rig.set_geometry({1920.0, 0.075});
  const Geometry back = rig.geometry();
  EXPECT_EQ(back.counts_per_revolution, 1920.0);
  EXPECT_NEAR(back.track_radius_m, 0.075, 1e-9);  // f32 of 75 mm, then / 1000
  EXPECT_EQ(device.geometry().counts_per_revolution, 1920.0);
  // The host's own check names the value; nothing reaches the device.
  EXPECT_EQ(version_1_1_error_of([&] { rig.set_geometry({0.0, 0.06}); }),
            "encoder counts per revolution 0.000000: the rig controller NIB-0001 needs a finite number above 0");
  EXPECT_EQ(device.geometry().counts_per_revolution, 1920.0);
}

TEST(UsbRigVersion11, ANewSerialIsWhatTheDeviceReportsAndListsFromThenOn) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  {
    UsbRigController rig;
    rig.set_serial("LAB-7");
    EXPECT_EQ(rig.identity().serial, "LAB-7");
    EXPECT_NE(version_1_1_error_of([&] { rig.set_serial("LAB 7"); }).find("byte 0x20"), std::string::npos);
  }
  const auto found = list_rig_controllers();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(describe(found[0]), "LAB-7 (bus 1, address 2, protocol 1.2, firmware emulated-1.2)");
}

TEST(UsbRigVersion11, TheBootloaderIsRefusedWhileTheMotorRuns) {
  Testbed testbed;
  EmulatedRig device(testbed.get(), EmulatedRigConfig{});
  UsbRigController rig;
  rig.set_speed(0.05);
  EXPECT_EQ(version_1_1_error_of([&] { rig.enter_bootloader(); }),
            "the rig controller NIB-0001 refused ENTER_BOOTLOADER (0x40) (STALL): out of order");
  EXPECT_FALSE(device.entered_bootloader());
  rig.stop();
  rig.enter_bootloader();
  EXPECT_TRUE(device.entered_bootloader());
}

TEST(UsbRigVersion11, AVersion10DeviceIsNotAskedAndTheErrorNamesBothVersions) {
  Testbed testbed;
  EmulatedRigConfig config;
  config.protocol_version = 0x0100;
  EmulatedRig device(testbed.get(), config);
  UsbRigController rig;  // 1.0 devices keep working
  EXPECT_EQ(version_1_1_error_of([&] { rig.geometry(); }),
            "the rig controller NIB-0001 speaks protocol 1.0; GET_GEOMETRY (0x34) needs 1.1 "
            "(`nibrig rig flash` updates its firmware)");
  EXPECT_NE(version_1_1_error_of([&] { rig.enter_bootloader(); }).find("ENTER_BOOTLOADER (0x40) needs 1.1"),
            std::string::npos);
  // The host did not send them: a 1.0 device would have refused them as unknown and said so.
  EXPECT_EQ(device.status().refused_request, 0);
}

}  // namespace
}  // namespace nibrig::rig::usb
