// The firmware's RAM on the simulated board: its static data and the stack at its worst, under a
// load that takes the main loop through every request, descriptor, EEPROM write, profile, fault and
// the fastest stream while every interrupt runs. The ATmega32U4 has 2560 bytes and nothing warns of
// a stack grown into .bss: at least 256 bytes must stay free.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/rig/usb/board_host.hpp"
#include "tests/rig/usb/hardware_guide.hpp"

namespace nibrig::rig::usb::testing {
namespace {

constexpr std::size_t kBoardRamBytes = 2560;

TEST(BoardMemory, TheStackAtItsWorstLeavesAQuarterKilobyteFree) {
  BoardHost host;
  SimulatedBoard& board = host.board();
  board.watch_stack();
  // Every descriptor the firmware sends, the serial's string built on the stack among them.
  for (std::uint8_t type_index : {0x01, 0x02}) {
    board.control({0x80, 6, 0, type_index, 0, 0, 255, 0}, {}, 255);
  }
  for (std::uint8_t string : {0, 1, 2, 3}) board.control({0x80, 6, string, 3, 0x09, 0x04, 255, 0}, {}, 255);
  host.require_out(Request::kSetFrameRate, 3000);
  host.require_out(Request::kSetStreaming, 1);
  host.require_in(Request::kIdentify, kIdentityBytes);
  const auto calibration = encode_calibration({50.0, 48.0, 1.0});
  host.require_out(Request::kSetCalibration, 0, 0, {calibration.begin(), calibration.end()});
  const auto geometry = encode_geometry({4480.0, 0.060});
  host.require_out(Request::kSetGeometry, 0, 0, {geometry.begin(), geometry.end()});
  const auto serial = encode_serial("LAB-STACK");
  host.require_out(Request::kSetSerial, 0, 0, {serial.begin(), serial.end()});
  host.require_out(Request::kZeroForce);
  // The longest profile, written and read back, then run at the sweep's speeds.
  std::vector<ProfilePoint> points;
  for (int i = 0; i < 64; ++i) points.push_back({0.02 * i, i % 2 == 0 ? 0.017 : 0.25});
  host.require_out(Request::kProfileBegin, 64);
  for (std::uint16_t first = 0; first < 64; first += 8) {
    host.require_out(Request::kProfileWrite, 0, first,
                     encode_points(std::span<const ProfilePoint>(points).subspan(first, 8)));
  }
  host.require_out(Request::kProfileEnd);
  for (std::uint16_t first = 0; first < 64; first += 8) host.require_in(Request::kProfileRead, 64, 0, first);
  host.require_out(Request::kStartProfile);
  host.run_us(600'000.0);
  // A fault's path, then a start again.
  host.board().jam(true);
  host.run_us(700'000.0);
  host.board().jam(false);
  host.set_speed_mm_s(250.0f);
  host.run_us(300'000.0);
  host.require_in(Request::kGetCalibration, kCalibrationBytes);
  host.require_in(Request::kGetGeometry, kGeometryBytes);
  host.status();

  const SimulatedBoard::StackUse& use = board.stack_use();
  const long free_bytes = static_cast<long>(kBoardRamBytes) - static_cast<long>(use.static_bytes + use.main_bytes + use.interrupt_bytes);
  std::printf("RAM: %zu B static, stack %zu B in the main loop + %zu B in the deepest interrupt: %ld B free of %zu\n",
              use.static_bytes, use.main_bytes, use.interrupt_bytes, free_bytes, kBoardRamBytes);
  RecordProperty("ram_static_bytes", std::to_string(use.static_bytes));
  RecordProperty("stack_main_bytes", std::to_string(use.main_bytes));
  RecordProperty("stack_interrupt_bytes", std::to_string(use.interrupt_bytes));
  RecordProperty("ram_free_bytes", std::to_string(free_bytes));
  EXPECT_GT(use.main_bytes, 0u);
  EXPECT_GT(use.interrupt_bytes, 0u);
  EXPECT_GE(free_bytes, 256);
  // The guide's figures, to the byte for static data (the linker's) and to 16 bytes for the stack
  // (a load a little unlike this one may go a call deeper).
  EXPECT_EQ(static_cast<double>(use.static_bytes), hardware_guide_figure("RAM taken by static data"));
  EXPECT_NEAR(static_cast<double>(free_bytes), hardware_guide_figure("RAM free at the stack's worst"), 16.0);
}

}  // namespace
}  // namespace nibrig::rig::usb::testing
