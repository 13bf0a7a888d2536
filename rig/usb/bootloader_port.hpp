// Finding an ATmega32U4 board's Caterina bootloader: after a reset (or ENTER_BOOTLOADER) it shows
// up for 8 s as a USB serial port with a VID:PID of its own, which sysfs ties to its tty.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace nibrig::rig::usb {

struct BootloaderId {
  std::uint16_t vendor;
  std::uint16_t product;
  const char* board;
};

// The bootloaders of the boards the reference controller runs on (rig/firmware).
inline constexpr BootloaderId kCaterinaBootloaders[] = {
    {0x2341, 0x0036, "Arduino Leonardo"},
    {0x2341, 0x0037, "Arduino Micro"},
    {0x1B4F, 0x9205, "SparkFun Pro Micro 5V"},
    {0x1B4F, 0x9207, "SparkFun Pro Micro 3.3V"},
    {0x2A03, 0x0036, "Arduino Leonardo (arduino.org)"},
};

struct SerialPort {
  std::string device;  // /dev/ttyACM0
  std::uint16_t vendor = 0, product = 0;  // of its USB device; 0 when it has none
  std::string board;   // the bootloader's board, empty when it is not a known bootloader
};

// Every tty in /sys/class/tty with a USB device above it, bootloader or not (the message for a
// port that never came lists them).
std::vector<SerialPort> usb_serial_ports();
// Those of usb_serial_ports() that are a known Caterina bootloader.
std::vector<SerialPort> bootloader_ports();

// "/dev/ttyACM0 (2341:0036 Arduino Leonardo)".
std::string describe(const SerialPort& port);

}  // namespace nibrig::rig::usb
