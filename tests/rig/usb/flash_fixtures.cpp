#include "tests/rig/usb/flash_fixtures.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <string>

namespace nibrig::rig::usb::testing {

void write_intel_hex(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(file);
  char text[16];
  for (std::size_t at = 0; at < bytes.size(); at += 16) {
    const std::size_t n = std::min<std::size_t>(16, bytes.size() - at);
    unsigned sum = static_cast<unsigned>(n + (at >> 8) + (at & 0xFF));
    std::snprintf(text, sizeof text, ":%02X%04X00", static_cast<unsigned>(n), static_cast<unsigned>(at));
    out << text;
    for (std::size_t i = 0; i < n; ++i) {
      std::snprintf(text, sizeof text, "%02X", bytes[at + i]);
      out << text;
      sum += bytes[at + i];
    }
    std::snprintf(text, sizeof text, "%02X\n", (0x100 - (sum & 0xFF)) & 0xFF);
    out << text;
  }
  out << ":00000001FF\n";
}

std::map<std::uint32_t, std::uint8_t> read_intel_hex(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::map<std::uint32_t, std::uint8_t> memory;
  std::uint32_t base = 0;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != ':') continue;
    std::vector<std::uint8_t> b;
    for (std::size_t i = 1; i + 1 < line.size(); i += 2) {
      b.push_back(static_cast<std::uint8_t>(std::stoul(line.substr(i, 2), nullptr, 16)));
    }
    unsigned sum = 0;
    for (auto x : b) sum += x;
    EXPECT_EQ(sum & 0xFF, 0u) << "checksum of " << line;
    const std::size_t n = b[0];
    const std::uint32_t offset = static_cast<std::uint32_t>((b[1] << 8) | b[2]);
    if (b[3] == 0x00) {
      for (std::size_t i = 0; i < n; ++i) memory[base + offset + static_cast<std::uint32_t>(i)] = b[4 + i];
    } else if (b[3] == 0x01) {
      break;
    } else if (b[3] == 0x02) {
      base = static_cast<std::uint32_t>((b[4] << 8) | b[5]) << 4;
    } else if (b[3] == 0x04) {
      base = static_cast<std::uint32_t>((b[4] << 8) | b[5]) << 16;
    }
  }
  return memory;
}

void add_usb_serial_port(UMockdevTestbed* testbed, const char* usb_name, const char* tty, unsigned vendor,
                         unsigned product) {
  char description[1024];
  std::snprintf(description, sizeof description,
                "P: /devices/usb1/%s\nE: SUBSYSTEM=usb\nE: DEVTYPE=usb_device\n"
                "A: idVendor=%04x\\n\nA: idProduct=%04x\\n\n",
                usb_name, vendor, product);
  GError* error = nullptr;
  ASSERT_TRUE(umockdev_testbed_add_from_string(testbed, description, &error)) << error->message;
  std::snprintf(description, sizeof description,
                "P: /devices/usb1/%s/%s:1.0/tty/%s\nN: %s\nE: SUBSYSTEM=tty\nE: DEVNAME=/dev/%s\n", usb_name,
                usb_name, tty, tty, tty);
  ASSERT_TRUE(umockdev_testbed_add_from_string(testbed, description, &error)) << error->message;
}

std::vector<std::uint8_t> flash_test_image(std::size_t bytes) {
  std::mt19937 random(31);
  std::vector<std::uint8_t> image(bytes);
  for (auto& b : image) b = static_cast<std::uint8_t>(random());
  return image;
}

}  // namespace nibrig::rig::usb::testing
