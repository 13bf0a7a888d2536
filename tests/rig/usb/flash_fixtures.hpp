// What the tests of `nibrig rig flash` share: Intel hex files written and read back, a board's
// USB serial port in a umockdev testbed, and a flash image to write.
#pragma once

#include <umockdev.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

namespace nibrig::rig::usb::testing {

// An Intel hex file of `bytes` from address 0, 16 bytes a record (what avr-objcopy writes).
void write_intel_hex(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes);
// What a hex file puts where: data records (00) with extended segment (02) and linear (04)
// addresses, to the end-of-file record (01). A bad checksum fails the test.
std::map<std::uint32_t, std::uint8_t> read_intel_hex(const std::filesystem::path& file);
// A USB device `usb_name` (under /sys/devices/usb1) with `vendor`:`product` and a tty below it,
// as the kernel's cdc_acm shows a board; the tty is a pty whose master side the test holds
// (umockdev_testbed_get_dev_fd).
void add_usb_serial_port(UMockdevTestbed* testbed, const char* usb_name, const char* tty, unsigned vendor,
                         unsigned product);
// `bytes` of seeded pseudo-random firmware.
std::vector<std::uint8_t> flash_test_image(std::size_t bytes);

}  // namespace nibrig::rig::usb::testing
