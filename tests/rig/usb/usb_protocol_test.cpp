// The wire layouts of rig/PROTOCOL.md against bytes written out by hand from its tables, so that a
// layout change in the code that the document does not share fails here.
#include "rig/usb/usb_protocol.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "rig/usb/usb_rig_error.hpp"

namespace nibrig::rig::usb {
namespace {

TEST(UsbProtocol, IdentityMatchesTheDocumentedLayout) {
  // 1.0, 512 points, 300.0 mm/s (0x43960000), 20.0 N (0x41A00000), 1000 Hz, 500..4000 Hz, 500 ms,
  // serial "RIG-7", firmware "1.2.3".
  std::vector<std::uint8_t> bytes = {0x00, 0x01, 0x00, 0x02, 0x00, 0x00, 0x96, 0x43, 0x00, 0x00,
                                     0xA0, 0x41, 0xE8, 0x03, 0xF4, 0x01, 0xA0, 0x0F, 0xF4, 0x01};
  const char serial[16] = "RIG-7";
  const char firmware[16] = "1.2.3";
  bytes.insert(bytes.end(), serial, serial + 16);
  bytes.insert(bytes.end(), firmware, firmware + 16);
  ASSERT_EQ(bytes.size(), kIdentityBytes);

  const Identity id = decode_identity(bytes);
  EXPECT_EQ(id.protocol_version, 0x0100);
  EXPECT_EQ(id.max_profile_points, 512);
  EXPECT_DOUBLE_EQ(id.max_speed_m_s, 0.3);  // 300 mm/s is exact in f32; /1000 in double
  EXPECT_DOUBLE_EQ(id.force_full_scale_N, 20.0);
  EXPECT_EQ(id.frame_rate_hz, 1000u);
  EXPECT_EQ(id.min_frame_rate_hz, 500u);
  EXPECT_EQ(id.max_frame_rate_hz, 4000u);
  EXPECT_EQ(id.watchdog_timeout_ms, 500u);
  EXPECT_EQ(id.serial, "RIG-7");
  EXPECT_EQ(id.firmware, "1.2.3");

  const auto encoded = encode_identity(id);
  EXPECT_EQ(std::vector<std::uint8_t>(encoded.begin(), encoded.end()), bytes);
}

TEST(UsbProtocol, ASixteenCharacterSerialNeedsNoTerminator) {
  Identity id;
  id.serial = "ABCDEFGHIJKLMNOP";
  EXPECT_EQ(decode_identity(encode_identity(id)).serial, "ABCDEFGHIJKLMNOP");
  id.serial = "ABCDEFGHIJKLMNOPQ";
  EXPECT_THROW(encode_identity(id), UsbRigError);
}

TEST(UsbProtocol, AShortReplyIsAnErrorNamingTheRequest) {
  const std::vector<std::uint8_t> short_reply(10, 0);
  try {
    decode_identity(short_reply);
    FAIL() << "a 10-byte IDENTIFY reply was accepted";
  } catch (const UsbRigError& e) {
    EXPECT_NE(std::string(e.what()).find("IDENTIFY reply has 10 bytes"), std::string::npos) << e.what();
  }
  EXPECT_THROW(decode_status(short_reply), UsbRigError);
}

TEST(UsbProtocol, StatusMatchesTheDocumentedLayout) {
  // flags 0x0030 (watchdog + running), mode 2, fault 3, next sequence 0x01020304, 17.5 mm/s
  // (0x418C0000), 12 points, last refusal SET_SPEED (0x10) out of range (3).
  const std::array<std::uint8_t, 16> bytes = {0x30, 0x00, 0x02, 0x03, 0x04, 0x03, 0x02, 0x01,
                                              0x00, 0x00, 0x8C, 0x41, 0x0C, 0x00, 0x10, 0x03};
  const DeviceStatus s = decode_status(bytes);
  EXPECT_EQ(s.flags, kWatchdogStopped | kProfileRunning);
  EXPECT_EQ(s.mode, Mode::kProfile);
  EXPECT_EQ(s.fault, Fault::kWatchdog);
  EXPECT_EQ(s.next_sequence, 0x01020304u);
  EXPECT_NEAR(s.speed_target_m_s, 0.0175, 1e-12);  // 17.5 is exact in f32
  EXPECT_EQ(s.profile_points, 12);
  EXPECT_EQ(s.refused_request, 0x10);
  EXPECT_EQ(s.refusal, 3);
  // A 1.1 reply leaves 1.2's fields at their "nothing to say".
  EXPECT_EQ(s.cause, FaultCause::kNone);
  EXPECT_EQ(s.reset_cause, ResetCause::kPowerOn);
  EXPECT_EQ(s.health, 0);
  const auto encoded = encode_status(s);
  EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), encoded.begin()));
  EXPECT_EQ(request_name(s.refused_request), "SET_SPEED (0x10)");
  EXPECT_EQ(refusal_text(s.refusal), "a value out of the device's range");
}

TEST(UsbProtocol, StatusOfVersion12SaysWhyWhatRestartedAndTheHealth) {
  // fault 2 (encoder), cause 9 (reversed), reset 2 (brown-out), health 1 (factory defaults).
  std::array<std::uint8_t, 20> bytes{};
  bytes[3] = 2;
  bytes[16] = 9;
  bytes[17] = 2;
  bytes[18] = 1;
  const DeviceStatus s = decode_status(bytes);
  EXPECT_EQ(s.fault, Fault::kEncoder);
  EXPECT_EQ(s.cause, FaultCause::kEncoderReversed);
  EXPECT_EQ(s.reset_cause, ResetCause::kBrownOut);
  EXPECT_EQ(s.health, kHealthFactoryDefaults);
  EXPECT_EQ(encode_status(s), bytes);
  EXPECT_NE(fault_cause_text(2, 9).find("swap encoder A and B"), std::string::npos);
  EXPECT_EQ(fault_cause_text(1, 0), fault_text(1));  // a 1.1 device: the fault alone
  EXPECT_EQ(fault_cause_text(1, 200), fault_text(1) + " (cause code 200)");
  EXPECT_EQ(reset_cause_text(2), "a brown-out (its supply dipped)");
}


TEST(UsbProtocol, CalibrationAndSpeedAreLittleEndianFloats) {
  // 1000.0 (0x447A0000), 250.0 (0x437A0000), 2.5 (0x40200000)
  const std::array<std::uint8_t, 12> bytes = {0x00, 0x00, 0x7A, 0x44, 0x00, 0x00,
                                              0x7A, 0x43, 0x00, 0x00, 0x20, 0x40};
  const ForceCalibration c = decode_calibration(bytes);
  EXPECT_EQ(c.normal_counts_per_N, 1000.0);
  EXPECT_EQ(c.tangential_counts_per_N, 250.0);
  EXPECT_EQ(c.lever_factor, 2.5);
  EXPECT_EQ(encode_calibration(c), bytes);

  // 0.25 m/s is 250 mm/s on the wire.
  const std::array<std::uint8_t, 4> speed = {0x00, 0x00, 0x7A, 0x43};
  EXPECT_EQ(encode_speed(0.25), speed);
  EXPECT_DOUBLE_EQ(decode_speed(speed), 0.25);
}

TEST(UsbProtocol, ProfilePointsKeepMillisecondsAndMillimetresPerSecond) {
  const std::vector<ProfilePoint> points = {{0.0, 0.017}, {2.0, 0.017}, {2.0, 0.25}};
  const std::vector<std::uint8_t> expected = {
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x88, 0x41,   // 0 ms, 17 mm/s (0x41880000)
      0xD0, 0x07, 0x00, 0x00, 0x00, 0x00, 0x88, 0x41,   // 2000 ms
      0xD0, 0x07, 0x00, 0x00, 0x00, 0x00, 0x7A, 0x43};  // 2000 ms, 250 mm/s
  EXPECT_EQ(encode_points(points), expected);
  const auto back = decode_points(expected);
  ASSERT_EQ(back.size(), 3u);
  EXPECT_DOUBLE_EQ(back[1].time_s, 2.0);
  EXPECT_NEAR(back[0].speed_m_s, 0.017, 1e-9);  // f32 of 17 mm/s is exact; m/s is /1000
  EXPECT_DOUBLE_EQ(back[2].speed_m_s, 0.25);
  // Time is kept to the millisecond, rounded to the nearest (PROTOCOL.md "Profile").
  const std::vector<ProfilePoint> fine = {{1.2346, 0.0}};
  EXPECT_DOUBLE_EQ(decode_points(encode_points(fine))[0].time_s, 1.235);
  EXPECT_THROW(decode_points(std::vector<std::uint8_t>(7, 0)), UsbRigError);
}

TEST(UsbProtocol, FramePacketDecodesEveryDocumentedField) {
  std::vector<std::uint8_t> packet = {
      2, 28, 0, 0,
      // frame 0: clock 0x0000000102030405 us, sequence 7, 100 mm/s (0x42C80000), 2.0 N
      // (0x40000000), -0.5 N (0xBF000000), flags kNormalForceSaturated|kProfileRunning (0x21)
      0x05, 0x04, 0x03, 0x02, 0x01, 0x00, 0x00, 0x00, 0x07, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC8, 0x42,
      0x00, 0x00, 0x00, 0x40, 0x00, 0x00, 0x00, 0xBF, 0x21, 0x00, 0x00, 0x00,
      // frame 1: clock +1000 us, sequence 8, zero values, no flags
      0xED, 0x07, 0x03, 0x02, 0x01, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  std::array<SensorFrame, kMaxFramesPerPacket> out{};
  const PacketDecode d = decode_frame_packet(packet, out);
  ASSERT_EQ(d.error, nullptr);
  ASSERT_EQ(d.frames, 2u);
  EXPECT_EQ(out[0].device_time_us, 0x0000000102030405ull);
  EXPECT_EQ(out[0].sequence, 7u);
  EXPECT_FLOAT_EQ(out[0].speed_m_s, 0.1f);
  EXPECT_EQ(out[0].normal_force_N, 2.0f);
  EXPECT_EQ(out[0].tangential_force_N, -0.5f);
  EXPECT_EQ(out[0].flags, kNormalForceSaturated | kProfileRunning);
  EXPECT_EQ(out[1].device_time_us, 0x0000000102030405ull + 1000);
  EXPECT_EQ(out[1].sequence, 8u);

  const std::array<SensorFrame, 2> frames = {out[0], out[1]};
  EXPECT_EQ(encode_frame_packet(frames), packet);
}

TEST(UsbProtocol, ALaterMinorVersionsLongerFramesAreRead) {
  // 32-byte frames: the host reads the first 28 and skips the 4 appended bytes.
  std::vector<std::uint8_t> packet = {1, 32, 0, 0};
  packet.resize(4 + 32, 0xEE);
  for (int i = 0; i < 28; ++i) packet[4 + i] = 0;
  packet[4 + 8] = 42;  // sequence
  std::array<SensorFrame, kMaxFramesPerPacket> out{};
  const PacketDecode d = decode_frame_packet(packet, out);
  ASSERT_EQ(d.frames, 1u) << (d.error ? d.error : "");
  EXPECT_EQ(out[0].sequence, 42u);
}

TEST(UsbProtocol, MalformedPacketsAreRefusedWithAReason) {
  std::array<SensorFrame, kMaxFramesPerPacket> out{};
  const std::vector<std::vector<std::uint8_t>> bad = {
      {},                                          // no header
      {0, 28, 0, 0},                               // no frames
      {19, 28, 0, 0},                              // too many frames
      {1, 20, 0, 0},                               // frames shorter than 1.0's
      std::vector<std::uint8_t>{1, 28, 0, 0, 1}};  // length does not match
  for (const auto& packet : bad) {
    const PacketDecode d = decode_frame_packet(packet, out);
    EXPECT_EQ(d.frames, 0u);
    EXPECT_NE(d.error, nullptr) << "packet of " << packet.size() << " bytes";
  }
}

}  // namespace
}  // namespace nibrig::rig::usb
