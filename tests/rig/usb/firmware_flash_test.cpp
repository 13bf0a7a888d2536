// `nibrig rig flash`'s library call with the real avrdude: the emulated controller (protocol 1.1)
// asked into its bootloader, a Caterina bootloader on a pty that umockdev shows as /dev/ttyACM0
// under a USB device with the Leonardo's bootloader VID:PID, and the flash memory it keeps
// compared byte for byte with the hex file's contents.
#include "rig/usb/firmware_flash.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <string>
#include <thread>
#include <vector>

#include "tests/rig/usb/avr109_bootloader.hpp"
#include "tests/rig/usb/flash_fixtures.hpp"
#include "tests/rig/usb/emulated_rig.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig::usb {
namespace {

using namespace std::chrono_literals;
using testing::add_usb_serial_port;
using testing::Avr109Bootloader;
using testing::flash_test_image;
using testing::read_intel_hex;
using testing::write_intel_hex;
using testing::EmulatedRig;
using testing::EmulatedRigConfig;
using testing::Testbed;

TEST(BootloaderPort, FindsTheCaterinaPortByItsUsbParentsIds) {
  Testbed testbed;
  add_usb_serial_port(testbed.get(), "1-4", "ttyUSB0", 0x0403, 0x6001);  // an FTDI cable: not a bootloader
  add_usb_serial_port(testbed.get(), "1-5", "ttyACM0", 0x2341, 0x0036);  // a Leonardo's Caterina
  const auto all = usb_serial_ports();
  EXPECT_EQ(all.size(), 2u);
  const auto found = bootloader_ports();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].device, "/dev/ttyACM0");
  EXPECT_EQ(describe(found[0]), "/dev/ttyACM0 (2341:0036 Arduino Leonardo)");
}

TEST(FirmwareFlash, AvrdudeWritesTheHexIntoTheBootloadersFlashAndTheControllerComesBack) {
  const auto dir = nibrig::test::scratch_dir("firmware_flash");
  const auto hex = dir / "nibrig-rig.hex";
  const auto image = flash_test_image(1000);  // eight pages, the last one partly
  write_intel_hex(hex, image);
  const auto in_file = read_intel_hex(hex);
  ASSERT_EQ(in_file.size(), image.size());

  Testbed testbed;
  auto device = std::make_unique<EmulatedRig>(testbed.get(), EmulatedRigConfig{"NIB-00F1", 2});
  FirmwareFlashOptions options;
  options.hex = hex;
  std::vector<std::string> steps;
  auto flashing = std::async(std::launch::async, [&] {
    return flash_firmware(options, [&](const std::string& s) { steps.push_back(s); });
  });
  // The hardware's part: the board leaves the bus for its bootloader, whose port appears...
  const auto limit = std::chrono::steady_clock::now() + 5s;
  while (!device->entered_bootloader() && std::chrono::steady_clock::now() < limit) std::this_thread::sleep_for(5ms);
  ASSERT_TRUE(device->entered_bootloader());
  device->unplug();
  add_usb_serial_port(testbed.get(), "1-5", "ttyACM0", 0x2341, 0x0036);
  const int master = umockdev_testbed_get_dev_fd(testbed.get(), "/dev/ttyACM0");
  ASSERT_GE(master, 0);
  Avr109Bootloader bootloader(master);
  // ...and after the upload it starts the new firmware: the controller is back.
  const auto upload_limit = std::chrono::steady_clock::now() + 30s;
  while (!bootloader.exited() && std::chrono::steady_clock::now() < upload_limit) std::this_thread::sleep_for(10ms);
  umockdev_testbed_remove_device(testbed.get(), "/sys/devices/usb1/1-5");
  device->replug(3);
  const FirmwareFlashResult result = flashing.get();

  EXPECT_EQ(result.port.device, "/dev/ttyACM0");
  EXPECT_EQ(result.controller.serial, "NIB-00F1");
  EXPECT_EQ(result.controller.protocol_version, kProtocolVersion);
  EXPECT_NE(result.avrdude_output.find("1000 bytes of flash verified"), std::string::npos) << result.avrdude_output;
  // Every byte of the hex where it says, the rest of the flash untouched (erased).
  const auto flash = bootloader.flash();
  for (const auto& [address, byte] : in_file) ASSERT_EQ(flash[address], byte) << "at 0x" << std::hex << address;
  for (std::size_t a = image.size(); a < flash.size(); ++a) ASSERT_EQ(flash[a], 0xFF) << "at 0x" << std::hex << a;
  // -D: no chip erase; the signature was read before anything was written.
  const std::string commands = bootloader.commands();
  EXPECT_EQ(commands.find('e'), std::string::npos) << commands;
  EXPECT_LT(commands.find('s'), commands.find('B')) << commands;
  EXPECT_EQ(steps.size(), 4u);
}

TEST(FirmwareFlash, AvrdudesRefusalIsReportedWithItsOutput) {
  const auto dir = nibrig::test::scratch_dir("firmware_flash_refused");
  const auto hex = dir / "nibrig-rig.hex";
  write_intel_hex(hex, flash_test_image(64));
  Testbed testbed;
  add_usb_serial_port(testbed.get(), "1-5", "ttyACM0", 0x2341, 0x0037);
  const int master = umockdev_testbed_get_dev_fd(testbed.get(), "/dev/ttyACM0");
  ASSERT_GE(master, 0);
  Avr109Bootloader bootloader(master, {0x1E, 0x95, 0x8A});  // an ATmega32U2's signature
  FirmwareFlashOptions options;
  options.hex = hex;
  options.port = "/dev/ttyACM0";  // reset pressed: no controller asked
  options.return_wait = 500ms;
  std::string message;
  try {
    flash_firmware(options, [](const std::string&) {});
  } catch (const FirmwareFlashError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("avrdude failed (exit code 1) writing " + hex.string() + " through /dev/ttyACM0:"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("signature"), std::string::npos) << message;  // avrdude's own words
  EXPECT_EQ(bootloader.commands().find('B'), std::string::npos);  // nothing was written
}

TEST(FirmwareFlash, NoBootloaderPortNamesTheSerialPortsThereAndWhatToDo) {
  const auto dir = nibrig::test::scratch_dir("firmware_flash_no_port");
  const auto hex = dir / "nibrig-rig.hex";
  write_intel_hex(hex, flash_test_image(64));
  Testbed testbed;
  add_usb_serial_port(testbed.get(), "1-4", "ttyUSB0", 0x0403, 0x6001);
  EmulatedRig device(testbed.get(), EmulatedRigConfig{"NIB-00F2", 2});
  FirmwareFlashOptions options;
  options.hex = hex;
  options.port_wait = 300ms;
  std::string message;
  try {
    flash_firmware(options, [](const std::string&) {});
  } catch (const FirmwareFlashError& e) {
    message = e.what();
  }
  EXPECT_EQ(message,
            "no bootloader's serial port (USB 2341:0036, 2341:0037, 1b4f:9205, 1b4f:9207, 2a03:0036) appeared "
            "within 0.3 s; USB serial ports now: /dev/ttyUSB0 (0403:6001). Press the board's reset button and "
            "run `nibrig rig flash --port /dev/ttyACMn` within the bootloader's 8 s");
  EXPECT_TRUE(device.entered_bootloader());
}

TEST(FirmwareFlash, AMissingAvrdudeSaysHowToInstallIt) {
  const auto hex = nibrig::test::scratch_dir("firmware_flash_no_avrdude") / "nibrig-rig.hex";
  write_intel_hex(hex, flash_test_image(16));
  std::string message;
  try {
    run_avrdude("/nonexistent/avrdude", "/dev/ttyACM0", hex);
  } catch (const FirmwareFlashError& e) {
    message = e.what();
  }
  EXPECT_EQ(message, "cannot run '/nonexistent/avrdude': is avrdude installed? (Debian: apt-get install avrdude)");
}

TEST(FirmwareFlash, AMissingHexSaysHowToBuildIt) {
  std::string message;
  try {
    find_firmware_hex(std::filesystem::path("/nonexistent/nibrig-rig.hex"));
  } catch (const FirmwareFlashError& e) {
    message = e.what();
  }
  EXPECT_EQ(message, "--hex /nonexistent/nibrig-rig.hex: no such file");
  if (std::getenv("NIBRIG_FIRMWARE_HEX") == nullptr && !std::filesystem::exists(NIBRIG_TEST_BINARY_DIR "/../rig/firmware/nibrig-rig.hex")) {
    try {
      find_firmware_hex(std::nullopt);
      message.clear();
    } catch (const FirmwareFlashError& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("-DNIBRIG_BUILD_FIRMWARE=ON"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace nibrig::rig::usb
