#include "rig/usb/bootloader_port.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace nibrig::rig::usb {
namespace {

namespace fs = std::filesystem;

// A sysfs attribute holding a hex number ("2341\n"); nullopt-like 0 and false when unreadable.
bool tty_hex_attribute(const fs::path& file, std::uint16_t& value) {
  std::ifstream in(file);
  unsigned v = 0;
  if (!(in >> std::hex >> v) || v > 0xFFFF) return false;
  value = static_cast<std::uint16_t>(v);
  return true;
}

// The tty's device folder, by its class link followed by hand: realpath() would bypass a test's
// umockdev sysfs, readlink() does not.
fs::path tty_device_folder(const fs::path& class_entry) {
  std::error_code ec;
  const fs::path target = fs::read_symlink(class_entry, ec);
  if (ec) return class_entry;
  return (class_entry.parent_path() / target).lexically_normal();
}

}  // namespace

std::vector<SerialPort> usb_serial_ports() {
  std::vector<SerialPort> ports;
  std::error_code ec;
  fs::directory_iterator entries("/sys/class/tty", ec);
  if (ec) return ports;
  for (const auto& entry : entries) {
    const std::string name = entry.path().filename().string();
    // The USB device is the nearest folder above the tty with idVendor and idProduct.
    for (fs::path up = tty_device_folder(entry.path()); up.has_relative_path() && up != up.parent_path();
         up = up.parent_path()) {
      SerialPort port;
      if (tty_hex_attribute(up / "idVendor", port.vendor) && tty_hex_attribute(up / "idProduct", port.product)) {
        port.device = "/dev/" + name;
        for (const auto& b : kCaterinaBootloaders) {
          if (b.vendor == port.vendor && b.product == port.product) port.board = b.board;
        }
        ports.push_back(port);
        break;
      }
    }
  }
  return ports;
}

std::vector<SerialPort> bootloader_ports() {
  std::vector<SerialPort> found;
  for (auto& p : usb_serial_ports()) {
    if (!p.board.empty()) found.push_back(p);
  }
  return found;
}

std::string describe(const SerialPort& port) {
  char id[16];
  std::snprintf(id, sizeof id, "%04x:%04x", static_cast<unsigned>(port.vendor), static_cast<unsigned>(port.product));
  return port.device + " (" + id + (port.board.empty() ? "" : " " + port.board) + ")";
}

}  // namespace nibrig::rig::usb
