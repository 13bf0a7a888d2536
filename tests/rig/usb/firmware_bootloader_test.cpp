// ENTER_BOOTLOADER on the real firmware (simulated board): what `nibrig rig flash` relies on before
// avrdude can talk to the board's Caterina bootloader. Caterina stays in the bootloader after a
// watchdog reset when it finds 0x7777 at 0x0800 (older builds) or at the top of RAM (newer ones).
// simavr 1.6 does not carry out the watchdog's reset (the firmware is seen waiting for it, with the
// watchdog armed), so the test checks the handshake up to there.
#include <gtest/gtest.h>

#include <cerrno>

#include "tests/rig/usb/firmware_rig.hpp"
#include "tests/rig/usb/simulated_board.hpp"

namespace nibrig::rig::usb::testing {
namespace {

constexpr std::uint16_t kUdcon = 0xE0, kWdtcsr = 0x60, kRamEnd = 0x0AFF;
constexpr std::array<std::uint8_t, 8> kEnterBootloader = {0x40, 0x40, 0x42, 0x4E, 0, 0, 0, 0};

std::uint16_t word_at(const SimulatedBoard& board, std::uint16_t address) {
  return static_cast<std::uint16_t>(board.data(address) | (board.data(address + 1) << 8));
}

TEST(FirmwareBootloader, LeavesTheBusAndArmsTheWatchdogWithCaterinasKey) {
  SimulatedBoard board(firmware_elf());
  board.enumerate(2);
  ASSERT_EQ(board.control(kEnterBootloader).status, 0);  // answered before it leaves
  board.run_us(60'000.0);  // its 50 ms off the bus, then the watchdog
  EXPECT_TRUE(board.data(kUdcon) & 1) << "still attached to the bus";
  EXPECT_EQ(word_at(board, 0x0800), 0x7777);
  EXPECT_EQ(word_at(board, kRamEnd - 1), 0x7777);
  // WDE set, 15 ms (WDP bits 0): a reset follows, which Caterina turns into the bootloader.
  EXPECT_TRUE(board.data(kWdtcsr) & (1 << 3));
  EXPECT_EQ(board.data(kWdtcsr) & 0x27, 0);
  EXPECT_EQ(board.duty(), 0.0);  // the motor is left stopped
}

TEST(FirmwareBootloader, RefusesAWrongKeyAndARunningMotor) {
  SimulatedBoard board(firmware_elf());
  board.enumerate(2);
  EXPECT_EQ(board.control({0x40, 0x40, 0x00, 0x00, 0, 0, 0, 0}).status, -EPIPE);
  const std::vector<std::uint8_t> speed = {0, 0, 0x48, 0x42};  // 50 mm/s as f32
  ASSERT_EQ(board.control({0x40, 0x10, 0, 0, 0, 0, 4, 0}, speed).status, 0);
  EXPECT_EQ(board.control(kEnterBootloader).status, -EPIPE);  // refused (4) while the motor runs
  const auto status = board.control({0xC0, 0x02, 0, 0, 0, 0, 16, 0}, {}, 16);
  ASSERT_EQ(status.in.size(), 16u);
  EXPECT_EQ(status.in[14], 0x40);  // the refused request
  EXPECT_EQ(status.in[15], 4);     // out of order
  board.run_us(60'000.0);
  EXPECT_FALSE(board.data(kUdcon) & 1);  // still on the bus
}

}  // namespace
}  // namespace nibrig::rig::usb::testing
