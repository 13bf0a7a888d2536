// What the firmware keeps in the ATmega32U4's EEPROM, on the simulated chip: calibration, geometry,
// serial and the force zero survive a power cycle (a new board from the old one's EEPROM), and a
// chip with an erased EEPROM gives itself a serial and the factory calibration, and keeps them.
#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "rig/firmware/rig_device.h"
#include "tests/rig/usb/board_host.hpp"

namespace nibrig::rig::usb::testing {
namespace {

// The amplifier's 0.255 V/N into the 10-bit ADC at 5 V (TurntablePhysics).
constexpr double kPersistCountsPerN = 0.255 * 1024.0 / 5.0;

// Runs until the firmware has written its persistent state out (it writes a byte a loop, each
// taking the EEPROM's 3.4 ms), at most 2 s.
void wait_for_eeprom(BoardHost& host) {
  for (int i = 0; i < 40; ++i) {
    host.run_us(50'000.0);
    if (host.board().read_symbol("persist_next", 1)[0] > sizeof(rig_persist)) return;
  }
  FAIL() << "the firmware did not finish writing its EEPROM in 2 s";
}

// The mean normal force of the frames sampled over `us`, from a frame period after the force was
// set (a frame averages the period before its sample).
double mean_normal_force(BoardHost& host, double newtons, double us) {
  host.board().set_normal_force(newtons);
  const double from = host.sim_us() + 1000.0;
  host.clear_records();
  host.run_us(us);
  double sum = 0.0;
  int n = 0;
  for (const ReceivedFrame& f : host.frames()) {
    if (host.sim_us_at_device_us(f.frame.device_time_us) < from + 1000.0) continue;
    sum += f.frame.normal_force_N;
    ++n;
  }
  return n == 0 ? NAN : sum / n;
}

TEST(BoardPersist, CalibrationGeometrySerialAndZeroSurviveAPowerCycle) {
  std::vector<std::uint8_t> eeprom;
  {
    BoardHost host;
    const auto calibration = encode_calibration({50.0, 48.0, 1.1});
    host.require_out(Request::kSetCalibration, 0, 0, {calibration.begin(), calibration.end()});
    const auto geometry = encode_geometry({4000.0, 0.055});
    host.require_out(Request::kSetGeometry, 0, 0, {geometry.begin(), geometry.end()});
    const auto serial = encode_serial("LAB-7");
    host.require_out(Request::kSetSerial, 0, 0, {serial.begin(), serial.end()});
    // The arm resting on the cell with 0.7 N is the new zero.
    host.board().set_normal_force(0.7);
    host.run_us(5'000.0);  // the arm settles: the first frame zeroed averages the period before the request
    host.require_out(Request::kSetStreaming, 1);
    host.require_out(Request::kZeroForce);
    host.run_us(150'000.0);  // its 100 ms of frames
    wait_for_eeprom(host);
    eeprom = host.board().eeprom();
  }

  BoardHost again(eeprom);
  const Identity id = decode_identity(again.require_in(Request::kIdentify, kIdentityBytes));
  EXPECT_EQ(id.serial, "LAB-7");
  const ForceCalibration c = decode_calibration(again.require_in(Request::kGetCalibration, kCalibrationBytes));
  EXPECT_FLOAT_EQ(c.normal_counts_per_N, 50.0f);  // f32 through the EEPROM, bit for bit
  EXPECT_FLOAT_EQ(c.tangential_counts_per_N, 48.0f);
  EXPECT_FLOAT_EQ(c.lever_factor, 1.1f);
  const Geometry g = decode_geometry(again.require_in(Request::kGetGeometry, kGeometryBytes));
  EXPECT_FLOAT_EQ(g.counts_per_revolution, 4000.0f);
  EXPECT_NEAR(g.track_radius_m, 0.055, 1e-7);  // f32 of 55 mm, in metres

  // The same 0.7 N reads as zero, and a newton more as the new calibration says: the zero in
  // counts survived. A constant voltage gives one ADC count, so the zero is exact to the count
  // the mean was rounded to (half a count is 0.011 N here); 1 N more reads to that and a count.
  again.require_out(Request::kSetStreaming, 1);
  const double newtons_per_count = 1.1 / 50.0;
  EXPECT_NEAR(mean_normal_force(again, 0.7, 50'000.0), 0.0, 0.5 * newtons_per_count);
  EXPECT_NEAR(mean_normal_force(again, 1.7, 50'000.0), kPersistCountsPerN * newtons_per_count, 1.5 * newtons_per_count);
}

TEST(BoardPersist, AnErasedChipMakesItsSerialAndFactoryCalibrationAndKeepsThem) {
  std::string serial;
  std::vector<std::uint8_t> eeprom;
  {
    BoardHost host;  // an erased EEPROM
    const Identity id = decode_identity(host.require_in(Request::kIdentify, kIdentityBytes));
    serial = id.serial;
    EXPECT_TRUE(std::regex_match(serial, std::regex("NIB-[0-9A-F]{4}"))) << serial;
    // The status tells the host the calibration is the factory's (PROTOCOL.md 1.2 "health").
    EXPECT_EQ(host.status().health & kHealthFactoryDefaults, kHealthFactoryDefaults);
    const ForceCalibration c = decode_calibration(host.require_in(Request::kGetCalibration, kCalibrationBytes));
    rig_persist factory;
    rig_persist_defaults(&factory);
    EXPECT_FLOAT_EQ(c.normal_counts_per_N, factory.counts_per_N[0]);
    EXPECT_FLOAT_EQ(c.tangential_counts_per_N, factory.counts_per_N[1]);
    EXPECT_FLOAT_EQ(c.lever_factor, factory.lever);
    const Geometry g = decode_geometry(host.require_in(Request::kGetGeometry, kGeometryBytes));
    EXPECT_FLOAT_EQ(g.counts_per_revolution, factory.counts_per_rev);
    EXPECT_NEAR(g.track_radius_m * 1e3, factory.radius_mm, 1e-4);
    wait_for_eeprom(host);
    eeprom = host.board().eeprom();
  }
  // The key last (0x4E31, little-endian): a write torn by a power cut leaves none.
  EXPECT_EQ(eeprom[0], 0x31);
  EXPECT_EQ(eeprom[1], 0x4E);
  BoardHost again(eeprom);
  EXPECT_EQ(decode_identity(again.require_in(Request::kIdentify, kIdentityBytes)).serial, serial);
  EXPECT_EQ(again.status().health & kHealthFactoryDefaults, 0);  // its own record now
}

// A record with a valid key and values no rig has (a bit flipped by a brown-out during a write, a
// different firmware's layout): the factory values, a new serial, and the status says so.
TEST(BoardPersist, ACorruptRecordFallsBackToTheFactoryValuesAndSaysSo) {
  std::vector<std::uint8_t> eeprom(1024, 0xFF);
  eeprom[0] = 0x31;  // the key, little-endian
  eeprom[1] = 0x4E;
  for (std::size_t i = 2; i < 2 + sizeof(rig_persist); ++i) eeprom[i] = 0xFF;  // NaN floats, a 0xFF serial
  BoardHost host(eeprom);
  const DeviceStatus s = host.status();
  EXPECT_EQ(s.health & kHealthFactoryDefaults, kHealthFactoryDefaults);
  const ForceCalibration c = decode_calibration(host.require_in(Request::kGetCalibration, kCalibrationBytes));
  rig_persist factory;
  rig_persist_defaults(&factory);
  EXPECT_FLOAT_EQ(c.normal_counts_per_N, factory.counts_per_N[0]);
  EXPECT_FLOAT_EQ(c.lever_factor, factory.lever);
  EXPECT_TRUE(std::regex_match(decode_identity(host.require_in(Request::kIdentify, kIdentityBytes)).serial,
                               std::regex("NIB-[0-9A-F]{4}")));
}

// Calibrations and geometries no part of the guide gives: refused with the range reason, nothing
// changed. The reference design's values and the paper's lever with a matching cell are taken.
TEST(BoardCalibration, NonsenseIsRefusedAndChangesNothing) {
  BoardHost host;
  struct Nonsense {
    const char* what;
    ForceCalibration calibration;
  };
  for (const Nonsense& n : {Nonsense{"a count of 0.2 N: a tenth of the load", {5.0, 52.2, 1.0}},
                            Nonsense{"a full scale under twice the load", {52.2, 52.2, 0.08}},
                            Nonsense{"not a number", {NAN, 52.2, 1.0}}}) {
    const auto bytes = encode_calibration(n.calibration);
    EXPECT_EQ(host.out(Request::kSetCalibration, 0, 0, {bytes.begin(), bytes.end()}).status, -EPIPE) << n.what;
    const DeviceStatus s = host.status();
    EXPECT_EQ(s.refused_request, static_cast<std::uint8_t>(Request::kSetCalibration)) << n.what;
    EXPECT_EQ(s.refusal, static_cast<std::uint8_t>(Refusal::kRange)) << n.what;
  }
  const ForceCalibration kept = decode_calibration(host.require_in(Request::kGetCalibration, kCalibrationBytes));
  EXPECT_FLOAT_EQ(kept.normal_counts_per_N, 52.2f);
  EXPECT_FLOAT_EQ(kept.lever_factor, 1.0f);
  for (const Geometry& g : {Geometry{4480.0, 0.150}, Geometry{44.8, 0.060}}) {
    const auto bytes = encode_geometry(g);
    EXPECT_EQ(host.out(Request::kSetGeometry, 0, 0, {bytes.begin(), bytes.end()}).status, -EPIPE);
  }
  // The paper's lever, which puts 14 times the tip's force on the cell: a cell 14 times stiffer.
  const auto paper = encode_calibration({3.75, 3.75, 1.0 / 14.0});
  host.require_out(Request::kSetCalibration, 0, 0, {paper.begin(), paper.end()});
}

}  // namespace
}  // namespace nibrig::rig::usb::testing
