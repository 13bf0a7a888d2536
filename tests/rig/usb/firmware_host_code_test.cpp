// The firmware's own C files compiled for the host (nibrig_firmware_host), for what simavr's USB
// model cannot carry and what is cheap to check exhaustively here.
//
// simavr answers a NAK on a bulk IN endpoint as a zero-length packet, so neither its harness nor
// FirmwareRig can tell a real zero-length packet from "no data yet": a packet whose length were a
// multiple of 64 bytes would need a ZLP to end its transfer, and the simulated host would wait for
// the next packet instead. So the packet builder must never make one; that is checked here for every
// count of frames the fifo can hold and every position of its wrapping indices. simavr's endpoints
// also have one bank where the firmware configures two on the chip (UECFG1X's EPBK0): the
// double-buffered stream is not exercised in simulation, and there is nothing of it to test here.
//
// Then rig_control's refusals: every request code in every direction, every wrong wLength, wValue
// and wIndex, out-of-range values and out-of-order profile requests.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "rig/usb/usb_protocol.hpp"

extern "C" {
#include "rig/firmware/frame_fifo.h"
#include "rig/firmware/rig_device.h"
}

namespace nibrig::rig::usb {
namespace {

// A frame encoded into the producer's slot, as the firmware's loop does.
bool fifo_push_frame(frame_fifo& q, std::uint64_t t_us, std::uint32_t sequence) {
  std::uint8_t* slot = frame_fifo_slot(&q);
  if (slot == nullptr) return false;
  const rig_frame f{t_us, sequence, 1.0f, {0.0f, 0.0f}, 0};
  rig_frame_encode(&f, slot);
  frame_fifo_push(&q);
  return true;
}

// A packet read out of the ring as the USB sender reads it: run by run, in USB packets of 64 bytes.
std::vector<std::uint8_t> fifo_take_packet(frame_fifo& q) {
  const std::uint16_t length = frame_fifo_begin_packet(&q);
  std::vector<std::uint8_t> packet;
  for (;;) {
    std::uint8_t room = 64;
    const std::uint8_t* bytes = nullptr;
    std::uint8_t n = 0;
    while (room > 0 && (n = frame_fifo_packet_span(&q, &bytes)) > 0) {
      n = std::min(n, room);
      packet.insert(packet.end(), bytes, bytes + n);
      frame_fifo_packet_advance(&q, n);
      room = static_cast<std::uint8_t>(room - n);
    }
    if (room > 0) break;  // a short USB packet ends the transfer
  }
  EXPECT_EQ(packet.size(), length);
  return packet;
}

TEST(FirmwareFramePackets, NoPacketIsAMultipleOf64BytesNorLongerThanItsBuffer) {
  // Every starting position of the one-byte indices (they wrap at 256), every fill.
  for (unsigned start = 0; start < 256; ++start) {
    for (unsigned fill = 0; fill <= FRAME_FIFO_SIZE; ++fill) {
      frame_fifo q{};
      q.head = static_cast<std::uint8_t>(start);
      q.tail = static_cast<std::uint8_t>(start);
      for (unsigned i = 0; i < fill; ++i) ASSERT_TRUE(fifo_push_frame(q, 1000ull * i, i));
      std::uint32_t expected = 0;
      while (frame_fifo_count(&q) > 0) {
        const std::vector<std::uint8_t> out = fifo_take_packet(q);
        ASSERT_LE(out.size(), PACKET_MAX_BYTES) << "start " << start << " fill " << fill;
        ASSERT_NE(out.size() % 64, 0u) << "start " << start << " fill " << fill;
        // The host's own decoder reads it, frames in order.
        std::array<SensorFrame, kMaxFramesPerPacket> decoded{};
        const PacketDecode d = decode_frame_packet(out, decoded);
        ASSERT_EQ(d.error, nullptr) << d.error;
        ASSERT_GE(d.frames, 1u);
        ASSERT_LE(d.frames, PACKET_MAX_FRAMES);
        for (std::size_t i = 0; i < d.frames; ++i) ASSERT_EQ(decoded[i].sequence, expected++);
      }
      ASSERT_EQ(expected, fill);
    }
  }
  // Every frame count a packet can carry, directly: 4 + 28 n.
  for (unsigned n = 1; n <= PACKET_MAX_FRAMES; ++n) EXPECT_NE((4 + RIG_FRAME_BYTES * n) % 64, 0u) << n;
}

// The packet's frames stay in the ring while it is sent: frames made meanwhile, and a clear (the
// stream switched off), leave its bytes as they were.
TEST(FirmwareFramePackets, APacketOnItsWayKeepsItsFramesWhatComesAfter) {
  frame_fifo q{};
  for (unsigned i = 0; i < 3; ++i) fifo_push_frame(q, 1000 * i, i);
  frame_fifo_begin_packet(&q);
  const std::uint8_t* bytes = nullptr;
  ASSERT_EQ(frame_fifo_packet_span(&q, &bytes), RIG_PACKET_HEADER_BYTES);
  frame_fifo_packet_advance(&q, RIG_PACKET_HEADER_BYTES);
  fifo_push_frame(q, 5000, 3);
  frame_fifo_clear(&q);
  EXPECT_EQ(frame_fifo_count(&q), 3u);  // the packet's three, not the one made after
  std::vector<std::uint8_t> rest;
  std::uint8_t n = 0;
  while ((n = frame_fifo_packet_span(&q, &bytes)) > 0) {
    rest.insert(rest.end(), bytes, bytes + n);
    frame_fifo_packet_advance(&q, n);
  }
  ASSERT_EQ(rest.size(), 3 * RIG_FRAME_BYTES);
  EXPECT_EQ(frame_fifo_count(&q), 0u);
  std::uint32_t third = 0;
  std::memcpy(&third, &rest[2 * RIG_FRAME_BYTES + 8], sizeof third);  // little-endian, as x86
  EXPECT_EQ(third, 2u);
}

TEST(FirmwareFramePackets, AFullFifoDropsTheNewestAndCountsIt) {
  frame_fifo q{};
  for (unsigned i = 0; i < FRAME_FIFO_SIZE; ++i) ASSERT_TRUE(fifo_push_frame(q, i, i));
  EXPECT_EQ(frame_fifo_slot(&q), nullptr);
  EXPECT_EQ(q.dropped, 1u);
  EXPECT_EQ(frame_fifo_count(&q), FRAME_FIFO_SIZE);
}

TEST(FirmwareFramePackets, APacketWaitsForEightFramesOrItsOldestsDeadline) {
  frame_fifo q{};
  EXPECT_FALSE(frame_fifo_ready(&q, 0, 4000, 1000));
  fifo_push_frame(q, 10'000, 0);
  EXPECT_FALSE(frame_fifo_ready(&q, 13'999, 4000, 1000));
  EXPECT_TRUE(frame_fifo_ready(&q, 14'000, 4000, 1000));
  for (unsigned i = 1; i < PACKET_MAX_FRAMES; ++i) fifo_push_frame(q, 10'000 + i, i);
  EXPECT_TRUE(frame_fifo_ready(&q, 10'010, 4000, 1000));
}

// At 1 kHz the fourth frame is the last before the oldest's 4 ms are up: the packet leaves with it,
// not a frame period later, so its newest frame reaches the host as soon as it is made.
TEST(FirmwareFramePackets, APacketLeavesWithTheLastFrameBeforeItsDeadline) {
  frame_fifo q{};
  for (unsigned i = 0; i < 3; ++i) fifo_push_frame(q, 10'000 + 1000 * i, i);
  EXPECT_FALSE(frame_fifo_ready(&q, 12'000, 4000, 1000));
  fifo_push_frame(q, 13'000, 3);
  EXPECT_TRUE(frame_fifo_ready(&q, 13'000, 4000, 1000));
}

// The protocol state of a fresh device, and one request at a time into it.
class FirmwareRequests : public ::testing::Test {
 protected:
  void SetUp() override {
    rig_persist p;
    rig_persist_defaults(&p);
    rig_init(&rig_, &p, 0);
  }

  rig_reply call(std::uint8_t type, std::uint8_t request, std::uint16_t value, std::uint16_t index,
                 std::uint16_t length, const std::vector<std::uint8_t>& data = {}) {
    const std::uint8_t setup[8] = {type,
                                   request,
                                   static_cast<std::uint8_t>(value),
                                   static_cast<std::uint8_t>(value >> 8),
                                   static_cast<std::uint8_t>(index),
                                   static_cast<std::uint8_t>(index >> 8),
                                   static_cast<std::uint8_t>(length),
                                   static_cast<std::uint8_t>(length >> 8)};
    // An OUT data stage is never longer than 64 bytes (the USB layer refuses longer ones); the
    // buffer is the largest wLength, so a wrong length can only be refused, never overread.
    std::vector<std::uint8_t> buffer(65536, 0);
    std::copy(data.begin(), data.end(), buffer.begin());
    rig_reply reply;
    rig_control(&rig_, setup, buffer.data(), now_us_ += 1000, &reply);
    return reply;
  }
  rig_reply out(Request r, std::uint16_t value, std::uint16_t index, const std::vector<std::uint8_t>& data) {
    return call(kRequestTypeOut, static_cast<std::uint8_t>(r), value, index, static_cast<std::uint16_t>(data.size()), data);
  }
  DeviceStatus status() {
    const rig_reply reply = call(kRequestTypeIn, static_cast<std::uint8_t>(Request::kGetStatus), 0, 0, kStatusBytes);
    EXPECT_EQ(reply.stall, 0);
    return decode_status(std::span<const std::uint8_t>(reply.data, reply.len));
  }
  // `reply` was a STALL for `why`, and GET_STATUS names it.
  void expect_refused(const rig_reply& reply, std::uint8_t request, Refusal why) {
    EXPECT_EQ(reply.stall, 1) << request_name(request);
    EXPECT_EQ(reply.persist, 0) << request_name(request);
    EXPECT_EQ(reply.bootloader, 0) << request_name(request);
    const DeviceStatus s = status();
    EXPECT_EQ(s.refused_request, request) << request_name(request);
    EXPECT_EQ(s.refusal, static_cast<std::uint8_t>(why)) << request_name(request);
  }

  ::rig rig_{};
  std::uint32_t now_us_ = 0;
};

struct FirmwareShape {
  Request request;
  bool in;
  std::uint16_t length;  // IN: the least; OUT: the exact; 0 with `points`: 8 n up to 64
  bool points;
  bool uses_value;
};

// PROTOCOL.md's requests, written out here from the document, not from the firmware's table.
const std::vector<FirmwareShape> kFirmwareShapes = {
    {Request::kIdentify, true, 52, false, false},       {Request::kGetStatus, true, 16, false, false},
    {Request::kSetStreaming, false, 0, false, true},    {Request::kSetSpeed, false, 4, false, false},
    {Request::kStartProfile, false, 0, false, false},   {Request::kStop, false, 0, false, false},
    {Request::kProfileBegin, false, 0, false, true},    {Request::kProfileWrite, false, 0, true, false},
    {Request::kProfileEnd, false, 0, false, false},     {Request::kProfileRead, true, 0, true, false},
    {Request::kZeroForce, false, 0, false, false},      {Request::kSetFrameRate, false, 0, false, true},
    {Request::kGetCalibration, true, 12, false, false}, {Request::kSetCalibration, false, 12, false, false},
    {Request::kGetGeometry, true, 8, false, false},     {Request::kSetGeometry, false, 8, false, false},
    {Request::kSetSerial, false, 16, false, false},     {Request::kEnterBootloader, false, 0, false, true},
};

bool firmware_length_ok(const FirmwareShape& s, unsigned length) {
  if (s.points) return length >= 8 && length <= 64 && length % 8 == 0;
  return s.in ? length >= s.length : length == s.length;
}

TEST_F(FirmwareRequests, UnknownCodesAndWrongDirectionsAreUnknown) {
  for (unsigned code = 0; code < 256; ++code) {
    const FirmwareShape* shape = nullptr;
    for (const FirmwareShape& s : kFirmwareShapes) {
      if (static_cast<unsigned>(s.request) == code) shape = &s;
    }
    // Vendor type in the wrong direction, and class, standard or interface-recipient types.
    for (const std::uint8_t type : {kRequestTypeIn, kRequestTypeOut, std::uint8_t{0x80}, std::uint8_t{0x00},
                                    std::uint8_t{0xA0}, std::uint8_t{0x41}, std::uint8_t{0xC1}}) {
      const bool right = shape != nullptr && type == (shape->in ? kRequestTypeIn : kRequestTypeOut);
      if (right) continue;
      const std::uint16_t length = shape != nullptr && shape->points ? 8 : (shape != nullptr ? shape->length : 0);
      expect_refused(call(type, static_cast<std::uint8_t>(code), 0, 0, length), static_cast<std::uint8_t>(code),
                     Refusal::kUnknown);
    }
  }
}

TEST_F(FirmwareRequests, EveryWrongLengthIsALengthRefusal) {
  std::vector<unsigned> lengths;
  for (unsigned l = 0; l <= 130; ++l) lengths.push_back(l);
  for (unsigned l : {255u, 256u, 512u, 4096u, 65535u}) lengths.push_back(l);
  for (const FirmwareShape& s : kFirmwareShapes) {
    for (unsigned length : lengths) {
      if (firmware_length_ok(s, length)) continue;
      const auto r = static_cast<std::uint8_t>(s.request);
      expect_refused(call(s.in ? kRequestTypeIn : kRequestTypeOut, r, 0, 0, static_cast<std::uint16_t>(length)), r,
                     Refusal::kLength);
    }
  }
  EXPECT_EQ(status().mode, Mode::kIdle);  // nothing refused did anything
}

TEST_F(FirmwareRequests, AValueOrIndexARequestDoesNotTakeIsARangeRefusal) {
  for (const FirmwareShape& s : kFirmwareShapes) {
    const auto r = static_cast<std::uint8_t>(s.request);
    const std::uint16_t length = s.points ? 8 : s.length;
    const std::uint8_t type = s.in ? kRequestTypeIn : kRequestTypeOut;
    if (!s.uses_value) {
      for (std::uint16_t value : {1, 0x100, 0xFFFF}) expect_refused(call(type, r, value, 0, length), r, Refusal::kRange);
    }
    if (!s.points) {
      for (std::uint16_t index : {1, 0x100, 0xFFFF}) expect_refused(call(type, r, 0, index, length), r, Refusal::kRange);
    }
  }
}

std::vector<std::uint8_t> firmware_f32s(std::initializer_list<float> values) {
  std::vector<std::uint8_t> b;
  for (float v : values) {
    std::uint8_t bytes[4];
    std::memcpy(bytes, &v, 4);  // little-endian, as the host and PROTOCOL.md
    b.insert(b.end(), bytes, bytes + 4);
  }
  return b;
}

TEST_F(FirmwareRequests, ValuesOutOfRangeAreRangeRefusals) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  for (std::uint16_t v : {2, 0xFFFF}) expect_refused(out(Request::kSetStreaming, v, 0, {}), 0x03, Refusal::kRange);
  for (std::uint16_t v : {0, 999, 3001, 4000, 0xFFFF}) expect_refused(out(Request::kSetFrameRate, v, 0, {}), 0x31, Refusal::kRange);
  for (std::uint16_t v : {0, 65, 0xFFFF}) expect_refused(out(Request::kProfileBegin, v, 0, {}), 0x20, Refusal::kRange);
  for (std::uint16_t v : {0, 0x4E41, 0x424E}) expect_refused(out(Request::kEnterBootloader, v, 0, {}), 0x40, Refusal::kRange);
  for (float v : {-1.0f, 300.01f, inf, nan}) expect_refused(out(Request::kSetSpeed, 0, 0, firmware_f32s({v})), 0x10, Refusal::kRange);
  for (float v : {0.0f, -1.0f, inf, nan}) {
    expect_refused(out(Request::kSetCalibration, 0, 0, firmware_f32s({v, 50.0f, 1.0f})), 0x33, Refusal::kRange);
    expect_refused(out(Request::kSetCalibration, 0, 0, firmware_f32s({50.0f, v, 1.0f})), 0x33, Refusal::kRange);
    expect_refused(out(Request::kSetCalibration, 0, 0, firmware_f32s({50.0f, 50.0f, v})), 0x33, Refusal::kRange);
    expect_refused(out(Request::kSetGeometry, 0, 0, firmware_f32s({v, 60.0f})), 0x35, Refusal::kRange);
    expect_refused(out(Request::kSetGeometry, 0, 0, firmware_f32s({4480.0f, v})), 0x35, Refusal::kRange);
  }
  auto serial = [](const char* text, std::size_t n) {
    std::vector<std::uint8_t> b(16, 0);
    std::memcpy(b.data(), text, n);
    return b;
  };
  const auto set_serial = static_cast<std::uint8_t>(Request::kSetSerial);
  expect_refused(out(Request::kSetSerial, 0, 0, serial("", 0)), set_serial,
                 Refusal::kRange);  // empty
  expect_refused(out(Request::kSetSerial, 0, 0, serial("NIB 1", 5)), set_serial,
                 Refusal::kRange);  // a space
  expect_refused(out(Request::kSetSerial, 0, 0, serial("NIB\x7F", 4)), set_serial,
                 Refusal::kRange);  // DEL
  expect_refused(out(Request::kSetSerial, 0, 0, serial("NIB\0X", 5)), set_serial,
                 Refusal::kRange);  // text after NUL
  // Nothing refused changed the device.
  const DeviceStatus s = status();
  EXPECT_EQ(s.mode, Mode::kIdle);
  // Copies: the firmware's structs are packed, and gtest would bind a reference to a member.
  const unsigned rate = rig_.frame_rate_hz, streaming = rig_.streaming;
  const float counts_per_N = rig_.persist.counts_per_N[0];
  EXPECT_EQ(rate, 1000u);
  EXPECT_EQ(streaming, 0u);
  EXPECT_FLOAT_EQ(counts_per_N, 52.2f);
  EXPECT_STREQ(rig_.persist.serial, "NIB-0000");
}

std::vector<std::uint8_t> firmware_points(std::initializer_list<std::pair<std::uint32_t, float>> points) {
  std::vector<std::uint8_t> b;
  for (const auto& p : points) {
    const std::uint32_t t = p.first;
    b.insert(b.end(), {static_cast<std::uint8_t>(t), static_cast<std::uint8_t>(t >> 8),
                       static_cast<std::uint8_t>(t >> 16), static_cast<std::uint8_t>(t >> 24)});
    const auto speed = firmware_f32s({p.second});
    b.insert(b.end(), speed.begin(), speed.end());
  }
  return b;
}

TEST_F(FirmwareRequests, ProfileRequestsOutOfOrderAreOrderRefusals) {
  // Nothing begun: no write, no end, no start, no read.
  expect_refused(out(Request::kProfileWrite, 0, 0, firmware_points({{0, 10.0f}})), 0x21, Refusal::kOrder);
  expect_refused(out(Request::kProfileEnd, 0, 0, {}), 0x22, Refusal::kOrder);
  expect_refused(out(Request::kStartProfile, 0, 0, {}), 0x11, Refusal::kOrder);
  expect_refused(call(kRequestTypeIn, 0x23, 0, 0, 8), 0x23, Refusal::kRange);  // no point held to read
  // Three points announced: a write that skips ahead, an end before all arrived, a write past them.
  EXPECT_EQ(out(Request::kProfileBegin, 3, 0, {}).stall, 0);
  expect_refused(out(Request::kProfileWrite, 0, 1, firmware_points({{0, 10.0f}})), 0x21, Refusal::kOrder);
  EXPECT_EQ(out(Request::kProfileWrite, 0, 0, firmware_points({{0, 10.0f}})).stall, 0);
  expect_refused(out(Request::kProfileWrite, 0, 0, firmware_points({{0, 10.0f}})), 0x21, Refusal::kOrder);  // again
  expect_refused(out(Request::kProfileEnd, 0, 0, {}), 0x22, Refusal::kOrder);
  expect_refused(out(Request::kProfileWrite, 0, 1, firmware_points({{100, 20.0f}, {200, 30.0f}, {300, 40.0f}})), 0x21,
                 Refusal::kRange);
  EXPECT_EQ(out(Request::kProfileWrite, 0, 1, firmware_points({{100, 20.0f}, {200, 30.0f}})).stall, 0);
  EXPECT_EQ(out(Request::kProfileEnd, 0, 0, {}).stall, 0);
  EXPECT_EQ(status().profile_points, 3u);
  expect_refused(call(kRequestTypeIn, 0x23, 0, 2, 16), 0x23, Refusal::kRange);  // points 2 and 3 of 3
  // A held profile starts; running, the bootloader is refused.
  EXPECT_EQ(out(Request::kStartProfile, 0, 0, {}).stall, 0);
  expect_refused(out(Request::kEnterBootloader, kBootloaderKey, 0, {}), 0x40, Refusal::kOrder);
}

TEST_F(FirmwareRequests, AProfileThatIsNotOneIsARangeRefusalAtItsEnd) {
  const std::vector<std::vector<std::uint8_t>> bad = {
      firmware_points({{5, 10.0f}, {100, 20.0f}}),                   // does not start at 0
      firmware_points({{0, 10.0f}, {100, 20.0f}, {50, 20.0f}}),      // goes back in time
      firmware_points({{0, 10.0f}, {100, 300.5f}}),                  // faster than the motor
      firmware_points({{0, 10.0f}, {100, -1.0f}}),                   // backwards
      firmware_points({{0, 10.0f}, {100, std::nanf("")}}),           // not a number
  };
  for (const auto& points : bad) {
    EXPECT_EQ(out(Request::kProfileBegin, static_cast<std::uint16_t>(points.size() / 8), 0, {}).stall, 0);
    EXPECT_EQ(out(Request::kProfileWrite, 0, 0, points).stall, 0);
    expect_refused(out(Request::kProfileEnd, 0, 0, {}), 0x22, Refusal::kRange);
    EXPECT_EQ(status().profile_points, 0u);
    expect_refused(out(Request::kStartProfile, 0, 0, {}), 0x11, Refusal::kOrder);
  }
}

}  // namespace
}  // namespace nibrig::rig::usb
