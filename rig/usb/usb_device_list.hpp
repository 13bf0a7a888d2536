// Finding rig controllers on the bus (VID/PID of PROTOCOL.md) and telling them apart by the serial
// their IDENTIFY reports: the list `nibrig rig devices` prints, and the open-by-serial the driver
// uses, whose error names what was found instead.
#pragma once

#include <libusb.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rig/usb/usb_protocol.hpp"

namespace nibrig::rig::usb {

struct RigControllerInfo {
  std::string serial;  // empty when the device could not be asked (see problem)
  int bus = 0;
  int address = 0;
  std::uint16_t protocol_version = 0;
  std::string firmware;
  std::string problem;  // why it could not be opened or identified; empty when fine
};

// "NIB-0001 (bus 1, address 2, protocol 1.1, firmware 1.1.0)".
std::string describe(const RigControllerInfo& info);

// Every rig controller on the bus, each opened for a moment to identify it. Throws UsbRigError only
// when libusb itself cannot start.
std::vector<RigControllerInfo> list_rig_controllers();
std::vector<RigControllerInfo> list_rig_controllers(libusb_context* context);

struct OpenedRig {
  libusb_device_handle* handle = nullptr;  // the caller's to close
  Identity identity;
  RigControllerInfo info;
};

// Opens the controller with this serial, or the only one when `serial` is empty. Without a match:
// nullopt, and `found` lists what was on the bus. Several controllers and no serial is a
// UsbRigError naming them (which one is meant cannot be guessed).
std::optional<OpenedRig> open_rig_controller(libusb_context* context, const std::string& serial,
                                             std::vector<RigControllerInfo>& found);

// The message for a missing controller: "no nibrig rig controller with serial X; found: A, B" or
// "... on the bus".
std::string missing_message(const std::string& serial, const std::vector<RigControllerInfo>& found);

}  // namespace nibrig::rig::usb
