#include "rig/usb/usb_control.hpp"

#include <cstdio>

#include "rig/usb/usb_rig_error.hpp"

namespace nibrig::rig::usb {

std::string libusb_error_text(int code) {
  return std::string(libusb_error_name(code)) + " (" + libusb_strerror(code) + ")";
}

std::vector<std::uint8_t> ControlChannel::in(Request request, std::uint16_t value,
                                             std::uint16_t index, std::uint16_t length,
                                             std::uint16_t min_length) {
  std::vector<std::uint8_t> reply(length);
  const int n = libusb_control_transfer(handle_, kRequestTypeIn, static_cast<std::uint8_t>(request),
                                        value, index, reply.data(), length, timeout_ms_);
  if (n < 0) fail(request, n);
  if (n < min_length) {
    throw UsbRigError(device_ + " answered " + request_name(static_cast<std::uint8_t>(request)) +
                      " with " + std::to_string(n) + " bytes; PROTOCOL.md defines " +
                      std::to_string(min_length));
  }
  reply.resize(static_cast<std::size_t>(n));
  return reply;
}

void ControlChannel::out(Request request, std::uint16_t value, std::uint16_t index,
                         std::span<const std::uint8_t> data) {
  // libusb takes a non-const buffer for both directions; an OUT transfer only reads it.
  std::vector<std::uint8_t> copy(data.begin(), data.end());
  const int n = libusb_control_transfer(handle_, kRequestTypeOut, static_cast<std::uint8_t>(request),
                                        value, index, copy.data(),
                                        static_cast<std::uint16_t>(copy.size()), timeout_ms_);
  if (n < 0) fail(request, n);
}

void ControlChannel::fail(Request request, int code) {
  const std::string what = request_name(static_cast<std::uint8_t>(request));
  if (code == LIBUSB_ERROR_PIPE) {
    // The device stalled: its status says why (PROTOCOL.md "Errors"). If even that fails, say
    // what is known.
    std::string why = "no reason could be read back";
    if (request != Request::kGetStatus) {
      std::vector<std::uint8_t> reply(kStatusBytes12);
      const int n = libusb_control_transfer(handle_, kRequestTypeIn,
                                            static_cast<std::uint8_t>(Request::kGetStatus), 0, 0,
                                            reply.data(), kStatusBytes12, timeout_ms_);
      if (n >= static_cast<int>(kStatusBytes)) {
        const DeviceStatus s = decode_status(std::span<const std::uint8_t>(reply.data(), static_cast<std::size_t>(n)));
        if (s.refused_request == static_cast<std::uint8_t>(request)) why = refusal_text(s.refusal);
      }
    }
    throw UsbRigError(device_ + " refused " + what + " (STALL): " + why);
  }
  if (code == LIBUSB_ERROR_NO_DEVICE) {
    throw UsbRigError(device_ + " is unplugged (" + what + " could not be sent)");
  }
  if (code == LIBUSB_ERROR_TIMEOUT) {
    throw UsbRigError(device_ + " did not answer " + what + " within " +
                      std::to_string(timeout_ms_) + " ms");
  }
  throw UsbRigError(device_ + ": " + what + " failed: " + libusb_error_text(code));
}

Identity ControlChannel::identify() {
  const Identity id = decode_identity(in(Request::kIdentify, 0, 0, 64, kIdentityBytes));
  if ((id.protocol_version >> 8) != (kProtocolVersion >> 8)) {
    char versions[64];
    std::snprintf(versions, sizeof versions, "%u.%u; this nibrig speaks %u.x",
                  id.protocol_version >> 8, id.protocol_version & 0xFFu, kProtocolVersion >> 8);
    throw UsbRigError(device_ + " speaks protocol " + versions);
  }
  return id;
}

DeviceStatus ControlChannel::status() {
  return decode_status(in(Request::kGetStatus, 0, 0, kStatusBytes12, kStatusBytes));
}

}  // namespace nibrig::rig::usb
