#include "rig/usb/usb_protocol.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "rig/usb/usb_rig_error.hpp"

namespace nibrig::rig::usb {
namespace {

// Explicit little-endian byte order, so the layout does not depend on the host's.
void put_u16(std::uint8_t* at, std::uint16_t v) {
  at[0] = static_cast<std::uint8_t>(v);
  at[1] = static_cast<std::uint8_t>(v >> 8);
}
void put_u32(std::uint8_t* at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) at[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void put_u64(std::uint8_t* at, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) at[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void put_f32(std::uint8_t* at, double v) { put_u32(at, std::bit_cast<std::uint32_t>(static_cast<float>(v))); }
std::uint16_t get_u16(const std::uint8_t* at) {
  return static_cast<std::uint16_t>(at[0] | (at[1] << 8));
}
std::uint32_t get_u32(const std::uint8_t* at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | at[i];
  return v;
}
std::uint64_t get_u64(const std::uint8_t* at) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | at[i];
  return v;
}
float get_f32(const std::uint8_t* at) { return std::bit_cast<float>(get_u32(at)); }

void put_text(std::uint8_t* at, const std::string& text, const char* field) {
  if (text.size() > 16) {
    throw UsbRigError(std::string(field) + " '" + text + "' is longer than the 16 characters PROTOCOL.md allows");
  }
  std::fill(at, at + 16, std::uint8_t{0});
  std::copy(text.begin(), text.end(), at);
}
std::string get_text(const std::uint8_t* at) {
  const auto* end = std::find(at, at + 16, std::uint8_t{0});
  return std::string(at, end);
}

void require_length(std::span<const std::uint8_t> bytes, std::size_t needed, const char* what) {
  if (bytes.size() < needed) {
    throw UsbRigError(std::string("the rig controller's ") + what + " reply has " +
                      std::to_string(bytes.size()) + " bytes; PROTOCOL.md defines " +
                      std::to_string(needed));
  }
}

constexpr double kMmPerM = 1000.0;

}  // namespace

std::string request_name(std::uint8_t request) {
  std::string_view name = "an unknown request";
  switch (static_cast<Request>(request)) {
    case Request::kIdentify: name = "IDENTIFY"; break;
    case Request::kGetStatus: name = "GET_STATUS"; break;
    case Request::kSetStreaming: name = "SET_STREAMING"; break;
    case Request::kSetSpeed: name = "SET_SPEED"; break;
    case Request::kStartProfile: name = "START_PROFILE"; break;
    case Request::kStop: name = "STOP"; break;
    case Request::kProfileBegin: name = "PROFILE_BEGIN"; break;
    case Request::kProfileWrite: name = "PROFILE_WRITE"; break;
    case Request::kProfileEnd: name = "PROFILE_END"; break;
    case Request::kProfileRead: name = "PROFILE_READ"; break;
    case Request::kZeroForce: name = "ZERO_FORCE"; break;
    case Request::kSetFrameRate: name = "SET_FRAME_RATE"; break;
    case Request::kGetCalibration: name = "GET_CALIBRATION"; break;
    case Request::kSetCalibration: name = "SET_CALIBRATION"; break;
    case Request::kGetGeometry: name = "GET_GEOMETRY"; break;
    case Request::kSetGeometry: name = "SET_GEOMETRY"; break;
    case Request::kSetSerial: name = "SET_SERIAL"; break;
    case Request::kEnterBootloader: name = "ENTER_BOOTLOADER"; break;
  }
  char code[8];
  std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned>(request));
  return std::string(name) + " (" + code + ")";
}

std::string refusal_text(std::uint8_t refusal) {
  switch (static_cast<Refusal>(refusal)) {
    case Refusal::kNone: return "no reason recorded";
    case Refusal::kUnknown: return "the device does not know the request";
    case Refusal::kLength: return "wrong data length";
    case Refusal::kRange: return "a value out of the device's range";
    case Refusal::kOrder: return "out of order";
  }
  return "reason code " + std::to_string(refusal);
}

std::string fault_text(std::uint8_t fault) {
  switch (static_cast<Fault>(fault)) {
    case Fault::kNone: return "none";
    case Fault::kMotor: return "motor fault (over-current, stall or over-temperature)";
    case Fault::kEncoder: return "encoder fault";
    case Fault::kWatchdog: return "motor stopped by the watchdog (the host was silent)";
    case Fault::kForce: return "force sensor fault";
  }
  return "fault code " + std::to_string(fault);
}

std::string fault_cause_text(std::uint8_t fault, std::uint8_t cause) {
  switch (static_cast<FaultCause>(cause)) {
    case FaultCause::kNone: break;
    case FaultCause::kStall:
      return "motor stalled: driven, drawing the current of a held rotor, and the disc did not turn; "
             "check that nothing jams the disc (the arm, a cable, the surface's clamp)";
    case FaultCause::kOverCurrent:
      return "motor over-current: more than the device asks of the motor, for too long; check the gearbox "
             "and bearings for binding and the motor's leads for a short";
    case FaultCause::kDriver:
      return "motor driver fault (nFAULT): the DRV8876 shut down on over-current, over-temperature or "
             "its supply under 4.5 V; check the motor's leads for a short and the 12 V supply";
    case FaultCause::kSupply:
      return "motor supply lost: driven, and no current flowed; the emergency stop is pressed, the "
             "T2A fuse is open or the 12 V adapter is unplugged";
    case FaultCause::kOverSpeed:
      return "motor over-speed: the encoder read a fifth beyond the highest speed; check the encoder's wiring and "
             "the geometry (nibrig rig calibrate --radius --counts-per-rev)";
    case FaultCause::kSlip:
      return "disc slipping: the motor turned at the target under a loaded tip and no friction was "
             "measured; tighten the disc's hub on its shaft and the jaw coupling";
    case FaultCause::kEncoderSilent:
      return "encoder silent: the motor turned and the encoder gave no count; check its cable "
             "(yellow to D3, white to D2, blue to 5 V, green to GND)";
    case FaultCause::kEncoderGlitch:
      return "encoder glitch: both channels changed at once; check for a loose encoder connector and "
             "keep its wires apart from the motor's leads";
    case FaultCause::kEncoderReversed:
      return "encoder reversed: the disc turned backwards while driven forwards; swap encoder A and B "
             "(yellow and white), or, if the disc itself turned the wrong way, the motor's two leads";
    case FaultCause::kEncoderChannel:
      return "encoder channel lost: one channel's edges alone while the motor turned; check the yellow "
             "(A, D3) and white (B, D2) wires";
    case FaultCause::kHostSilent:
      return "motor stopped by the watchdog: no request from the host for its timeout (nibrig ended, or the "
             "USB cable was pulled)";
    case FaultCause::kForceSaturated:
      return "force channel saturated for 100 ms while the disc turned: a load cell unplugged or "
             "overloaded (a hand on the holder); check its cable and the amplifier's REF (2.5 V)";
    case FaultCause::kForceNegative:
      return "normal force negative for 100 ms while the disc turned: the tip pulled up, or the normal "
             "cell's S+ and S- swapped";
  }
  if (cause != 0) return fault_text(fault) + " (cause code " + std::to_string(cause) + ")";
  return fault_text(fault);
}

std::string reset_cause_text(std::uint8_t cause) {
  switch (static_cast<ResetCause>(cause)) {
    case ResetCause::kPowerOn: return "power-on";
    case ResetCause::kExternal: return "its reset button";
    case ResetCause::kBrownOut: return "a brown-out (its supply dipped)";
    case ResetCause::kWatchdog: return "its watchdog (the firmware hung)";
  }
  return "reset code " + std::to_string(cause);
}

std::array<std::uint8_t, kIdentityBytes> encode_identity(const Identity& id) {
  std::array<std::uint8_t, kIdentityBytes> b{};
  put_u16(&b[0], id.protocol_version);
  put_u16(&b[2], id.max_profile_points);
  put_f32(&b[4], id.max_speed_m_s * kMmPerM);
  put_f32(&b[8], id.force_full_scale_N);
  put_u16(&b[12], static_cast<std::uint16_t>(id.frame_rate_hz));
  put_u16(&b[14], static_cast<std::uint16_t>(id.min_frame_rate_hz));
  put_u16(&b[16], static_cast<std::uint16_t>(id.max_frame_rate_hz));
  put_u16(&b[18], static_cast<std::uint16_t>(id.watchdog_timeout_ms));
  put_text(&b[20], id.serial, "the serial");
  put_text(&b[36], id.firmware, "the firmware version");
  return b;
}

Identity decode_identity(std::span<const std::uint8_t> b) {
  require_length(b, kIdentityBytes, "IDENTIFY");
  Identity id;
  id.protocol_version = get_u16(&b[0]);
  id.max_profile_points = get_u16(&b[2]);
  id.max_speed_m_s = get_f32(&b[4]) / kMmPerM;
  id.force_full_scale_N = get_f32(&b[8]);
  id.frame_rate_hz = get_u16(&b[12]);
  id.min_frame_rate_hz = get_u16(&b[14]);
  id.max_frame_rate_hz = get_u16(&b[16]);
  id.watchdog_timeout_ms = get_u16(&b[18]);
  id.serial = get_text(&b[20]);
  id.firmware = get_text(&b[36]);
  return id;
}

std::array<std::uint8_t, kStatusBytes12> encode_status(const DeviceStatus& s) {
  std::array<std::uint8_t, kStatusBytes12> b{};
  put_u16(&b[0], s.flags);
  b[2] = static_cast<std::uint8_t>(s.mode);
  b[3] = static_cast<std::uint8_t>(s.fault);
  put_u32(&b[4], s.next_sequence);
  put_f32(&b[8], s.speed_target_m_s * kMmPerM);
  put_u16(&b[12], s.profile_points);
  b[14] = s.refused_request;
  b[15] = s.refusal;
  b[16] = static_cast<std::uint8_t>(s.cause);
  b[17] = static_cast<std::uint8_t>(s.reset_cause);
  b[18] = s.health;
  return b;
}

DeviceStatus decode_status(std::span<const std::uint8_t> b) {
  require_length(b, kStatusBytes, "GET_STATUS");
  DeviceStatus s;
  s.flags = get_u16(&b[0]);
  s.mode = static_cast<Mode>(b[2]);
  s.fault = static_cast<Fault>(b[3]);
  s.next_sequence = get_u32(&b[4]);
  s.speed_target_m_s = get_f32(&b[8]) / kMmPerM;
  s.profile_points = get_u16(&b[12]);
  s.refused_request = b[14];
  s.refusal = b[15];
  if (b.size() >= kStatusBytes12) {
    s.cause = static_cast<FaultCause>(b[16]);
    s.reset_cause = static_cast<ResetCause>(b[17]);
    s.health = b[18];
  }
  return s;
}

std::array<std::uint8_t, kCalibrationBytes> encode_calibration(const ForceCalibration& c) {
  std::array<std::uint8_t, kCalibrationBytes> b{};
  put_f32(&b[0], c.normal_counts_per_N);
  put_f32(&b[4], c.tangential_counts_per_N);
  put_f32(&b[8], c.lever_factor);
  return b;
}

ForceCalibration decode_calibration(std::span<const std::uint8_t> b) {
  require_length(b, kCalibrationBytes, "GET_CALIBRATION");
  return {get_f32(&b[0]), get_f32(&b[4]), get_f32(&b[8])};
}

std::string version_text(std::uint16_t version) {
  return std::to_string(version >> 8) + "." + std::to_string(version & 0xFFu);
}

std::string serial_problem(const std::string& serial) {
  if (serial.empty()) return "a serial cannot be empty";
  if (serial.size() > kSerialBytes) {
    return "'" + serial + "' is " + std::to_string(serial.size()) + " characters; a serial holds at most 16";
  }
  for (std::size_t i = 0; i < serial.size(); ++i) {
    const auto c = static_cast<unsigned char>(serial[i]);
    if (c < 0x21 || c > 0x7E) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned>(c));
      return "character " + std::to_string(i + 1) + " of the serial is byte " + code +
             "; a serial is printable ASCII without spaces (0x21..0x7E)";
    }
  }
  return {};
}

std::array<std::uint8_t, kGeometryBytes> encode_geometry(const Geometry& g) {
  std::array<std::uint8_t, kGeometryBytes> b{};
  put_f32(&b[0], g.counts_per_revolution);
  put_f32(&b[4], g.track_radius_m * kMmPerM);
  return b;
}

Geometry decode_geometry(std::span<const std::uint8_t> b) {
  require_length(b, kGeometryBytes, "GET_GEOMETRY");
  return {get_f32(&b[0]), get_f32(&b[4]) / kMmPerM};
}

std::array<std::uint8_t, kSerialBytes> encode_serial(const std::string& serial) {
  if (const std::string problem = serial_problem(serial); !problem.empty()) throw UsbRigError(problem);
  std::array<std::uint8_t, kSerialBytes> b{};
  put_text(b.data(), serial, "the serial");
  return b;
}

std::string decode_serial(std::span<const std::uint8_t> b) {
  require_length(b, kSerialBytes, "SET_SERIAL");
  return get_text(b.data());
}

std::array<std::uint8_t, 4> encode_speed(double speed_m_s) {
  std::array<std::uint8_t, 4> b{};
  put_f32(b.data(), speed_m_s * kMmPerM);
  return b;
}

double decode_speed(std::span<const std::uint8_t> b) {
  require_length(b, 4, "SET_SPEED");
  return get_f32(b.data()) / kMmPerM;
}

std::vector<std::uint8_t> encode_points(std::span<const ProfilePoint> points) {
  std::vector<std::uint8_t> b(points.size() * kPointBytes);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double ms = std::round(points[i].time_s * 1000.0);
    if (!(ms >= 0.0 && ms <= 4294967295.0)) {
      throw UsbRigError("profile point " + std::to_string(i) + ": time " +
                        std::to_string(points[i].time_s) +
                        " s does not fit PROTOCOL.md's u32 milliseconds");
    }
    put_u32(&b[i * kPointBytes], static_cast<std::uint32_t>(ms));
    put_f32(&b[i * kPointBytes + 4], points[i].speed_m_s * kMmPerM);
  }
  return b;
}

std::vector<ProfilePoint> decode_points(std::span<const std::uint8_t> b) {
  if (b.size() % kPointBytes != 0) {
    throw UsbRigError("profile points: " + std::to_string(b.size()) +
                      " bytes is not a whole number of 8-byte points");
  }
  std::vector<ProfilePoint> points(b.size() / kPointBytes);
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i].time_s = get_u32(&b[i * kPointBytes]) / 1000.0;
    points[i].speed_m_s = get_f32(&b[i * kPointBytes + 4]) / kMmPerM;
  }
  return points;
}

PacketDecode decode_frame_packet(std::span<const std::uint8_t> p,
                                 std::span<SensorFrame, kMaxFramesPerPacket> out) noexcept {
  if (p.size() < kPacketHeaderBytes) return {0, "shorter than its 4-byte header"};
  const std::size_t count = p[0];
  const std::size_t frame_bytes = p[1];
  if (count == 0) return {0, "no frames"};
  if (count > kMaxFramesPerPacket) return {0, "more than 18 frames"};
  if (frame_bytes < kFrameBytes) return {0, "frames shorter than 28 bytes"};
  if (p.size() != kPacketHeaderBytes + count * frame_bytes) return {0, "length does not match its header"};
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* f = &p[kPacketHeaderBytes + i * frame_bytes];
    SensorFrame& frame = out[i];
    frame.device_time_us = get_u64(f);
    frame.sequence = get_u32(f + 8);
    frame.speed_m_s = static_cast<float>(get_f32(f + 12) / kMmPerM);
    frame.normal_force_N = get_f32(f + 16);
    frame.tangential_force_N = get_f32(f + 20);
    frame.flags = get_u16(f + 24);
  }
  return {count, nullptr};
}

std::vector<std::uint8_t> encode_frame_packet(std::span<const SensorFrame> frames) {
  if (frames.empty() || frames.size() > kMaxFramesPerPacket) {
    throw UsbRigError("a frame packet holds 1 to 18 frames, not " + std::to_string(frames.size()));
  }
  std::vector<std::uint8_t> p(kPacketHeaderBytes + frames.size() * kFrameBytes, 0);
  p[0] = static_cast<std::uint8_t>(frames.size());
  p[1] = static_cast<std::uint8_t>(kFrameBytes);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    std::uint8_t* f = &p[kPacketHeaderBytes + i * kFrameBytes];
    put_u64(f, frames[i].device_time_us);
    put_u32(f + 8, frames[i].sequence);
    put_f32(f + 12, static_cast<double>(frames[i].speed_m_s) * kMmPerM);
    put_f32(f + 16, frames[i].normal_force_N);
    put_f32(f + 20, frames[i].tangential_force_N);
    put_u16(f + 24, frames[i].flags);
  }
  return p;
}

}  // namespace nibrig::rig::usb
