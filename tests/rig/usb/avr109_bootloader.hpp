// An ATmega32U4 board's Caterina bootloader as avrdude meets it: the AVR109 commands on a serial
// port (here the master side of a pty, which umockdev puts behind a /dev/ttyACM node), with a
// flash memory that keeps what avrdude writes. The hardware this machine lacks, for the tests of
// `nibrig rig flash` with the real avrdude.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace nibrig::rig::usb::testing {

class Avr109Bootloader {
 public:
  static constexpr std::size_t kFlashBytes = 32 * 1024;
  static constexpr std::size_t kPageBytes = 128;  // the 32U4's SPM page: the block size it offers

  // Serves the pty master `fd` (not owned) on a thread of its own until 'E' (exit bootloader) or
  // the destructor. `signature` is what 's' reports (the 32U4's is 1E 95 87).
  explicit Avr109Bootloader(int fd, std::array<std::uint8_t, 3> signature = {0x1E, 0x95, 0x87});
  ~Avr109Bootloader();
  Avr109Bootloader(const Avr109Bootloader&) = delete;
  Avr109Bootloader& operator=(const Avr109Bootloader&) = delete;

  bool exited() const { return exited_.load(); }  // 'E' arrived: the board starts its firmware
  std::vector<std::uint8_t> flash() const;        // erased bytes are 0xFF
  std::string commands() const;                   // each command letter received, in order

 private:
  void serve();
  bool read_bytes(std::uint8_t* into, std::size_t n);
  void reply(std::initializer_list<std::uint8_t> bytes);
  void reply(const std::uint8_t* bytes, std::size_t n);

  int fd_;
  std::array<std::uint8_t, 3> signature_;
  mutable std::mutex mutex_;
  std::vector<std::uint8_t> flash_;
  std::string commands_;
  std::size_t address_ = 0;  // bytes (AVR109 addresses flash in words)
  std::atomic<bool> exited_{false};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace nibrig::rig::usb::testing
