// PROTOCOL.md's control requests, synchronously, on an open device: each failure becomes a
// UsbRigError naming the device and the request, and a STALL is explained by the refusal the device
// recorded in its status. Used by control threads and by the event thread when it reconnects.
#pragma once

#include <libusb.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rig/usb/usb_protocol.hpp"

namespace nibrig::rig::usb {

// "LIBUSB_ERROR_PIPE (Pipe error)": how errors quote libusb.
std::string libusb_error_text(int code);

class ControlChannel {
 public:
  // `device` names the device in errors ("the rig controller NIB-0001"); the handle stays the
  // caller's.
  ControlChannel(libusb_device_handle* handle, std::string device, unsigned timeout_ms = 1000)
      : handle_(handle), device_(std::move(device)), timeout_ms_(timeout_ms) {}

  // A reply of at least `min_length` bytes (asked for with wLength = `length`).
  std::vector<std::uint8_t> in(Request request, std::uint16_t value, std::uint16_t index,
                               std::uint16_t length, std::uint16_t min_length);
  void out(Request request, std::uint16_t value, std::uint16_t index,
           std::span<const std::uint8_t> data = {});

  // Throws when the device's major protocol version is not 1.
  Identity identify();
  DeviceStatus status();

 private:
  [[noreturn]] void fail(Request request, int code);

  libusb_device_handle* handle_;
  std::string device_;
  unsigned timeout_ms_;
};

}  // namespace nibrig::rig::usb
