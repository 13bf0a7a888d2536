// `nibrig rig flash`: the reference controller's firmware (rig/firmware) onto its board through the
// board's own bootloader. The controller is asked into the bootloader (ENTER_BOOTLOADER, protocol
// 1.1) unless the user pressed reset and named the port, the bootloader's serial port is found in
// sysfs, Debian's avrdude writes the hex by AVR109, and the controller's return is awaited.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "rig/usb/bootloader_port.hpp"
#include "rig/usb/usb_device_list.hpp"

namespace nibrig::rig::usb {

// A flash that could not be done: which step, and for avrdude its own output.
class FirmwareFlashError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The firmware to write: `given` (--hex), else $NIBRIG_FIRMWARE_HEX, else an installed nibrig's
// share/nibrig/firmware/nibrig-rig.hex, else what this build tree's firmware build writes. Throws
// FirmwareFlashError naming where it looked and how to build it.
std::filesystem::path find_firmware_hex(const std::optional<std::filesystem::path>& given);

struct FirmwareFlashOptions {
  std::string serial;                           // the controller to flash; empty: the only one
  std::optional<std::string> port;              // the bootloader waits here already (reset pressed)
  std::optional<std::filesystem::path> hex;     // see find_firmware_hex
  std::string avrdude = "avrdude";              // the program, found on PATH
  std::chrono::milliseconds port_wait{10000};   // for the bootloader's port to appear
  std::chrono::milliseconds return_wait{10000}; // for the controller to come back after the upload
};

struct FirmwareFlashResult {
  std::filesystem::path hex;
  SerialPort port;
  std::string avrdude_output;
  RigControllerInfo controller;  // as it came back: serial, protocol and firmware version
};

// Each step as it starts, for a face to show ("waiting for the bootloader's port").
using FlashProgress = std::function<void(const std::string& step)>;

// Throws FirmwareFlashError (no hex, no port, avrdude failed, the controller did not come back)
// or UsbRigError (the controller is missing, speaks 1.0, or refused: its motor runs).
FirmwareFlashResult flash_firmware(const FirmwareFlashOptions& options, const FlashProgress& progress);

// avrdude -p atmega32u4 -c avr109 -P PORT -b 57600 -D -U flash:w:HEX:i; its output (stdout and
// stderr together). Throws FirmwareFlashError with that output when it fails or cannot start.
std::string run_avrdude(const std::string& program, const std::string& port, const std::filesystem::path& hex);

}  // namespace nibrig::rig::usb
