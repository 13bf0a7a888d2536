// The rig controller's wire format (rig/PROTOCOL.md) as plain bytes in and out: request numbers,
// reply layouts and frame packets, with no libusb in sight, so that the driver and the tests'
// emulated device share one definition and each layout is tested against hand-built bytes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rig/sensor_frame.hpp"
#include "rig/speed_profile.hpp"

namespace nibrig::rig::usb {

inline constexpr std::uint16_t kVendorId = 0x1209;   // pid.codes
inline constexpr std::uint16_t kProductId = 0x000A;  // pid.codes' test range
inline constexpr int kInterface = 0;
inline constexpr std::uint8_t kStreamEndpoint = 0x81;
inline constexpr std::uint8_t kRequestTypeIn = 0xC0;   // vendor, device, device to host
inline constexpr std::uint8_t kRequestTypeOut = 0x40;  // vendor, device, host to device
inline constexpr std::uint16_t kProtocolVersion = 0x0102;
// The version that added GET/SET_GEOMETRY, SET_SERIAL and ENTER_BOOTLOADER.
inline constexpr std::uint16_t kGeometryVersion = 0x0101;
// The version whose status says why the motor stopped, what restarted the device, and its health.
inline constexpr std::uint16_t kFaultCauseVersion = 0x0102;
// ENTER_BOOTLOADER's wValue ("NB"): a stray request must not take the device off the bus.
inline constexpr std::uint16_t kBootloaderKey = 0x4E42;

enum class Request : std::uint8_t {
  kIdentify = 0x01,
  kGetStatus = 0x02,
  kSetStreaming = 0x03,
  kSetSpeed = 0x10,
  kStartProfile = 0x11,
  kStop = 0x12,
  kProfileBegin = 0x20,
  kProfileWrite = 0x21,
  kProfileEnd = 0x22,
  kProfileRead = 0x23,
  kZeroForce = 0x30,
  kSetFrameRate = 0x31,
  kGetCalibration = 0x32,
  kSetCalibration = 0x33,
  kGetGeometry = 0x34,
  kSetGeometry = 0x35,
  kSetSerial = 0x36,
  kEnterBootloader = 0x40,
};
// "IDENTIFY (0x01)": how errors name a request.
std::string request_name(std::uint8_t request);

// PROTOCOL.md "Errors": why the device refused a request.
enum class Refusal : std::uint8_t { kNone = 0, kUnknown = 1, kLength = 2, kRange = 3, kOrder = 4 };
std::string refusal_text(std::uint8_t refusal);

enum class Mode : std::uint8_t { kIdle = 0, kSpeed = 1, kProfile = 2, kProfileDone = 3 };
enum class Fault : std::uint8_t { kNone = 0, kMotor = 1, kEncoder = 2, kWatchdog = 3, kForce = 4 };
std::string fault_text(std::uint8_t fault);
// PROTOCOL.md "Fault causes" (1.2): why the device stopped the motor.
enum class FaultCause : std::uint8_t {
  kNone = 0,
  kStall = 1,
  kOverCurrent = 2,
  kDriver = 3,
  kSupply = 4,
  kOverSpeed = 5,
  kSlip = 6,
  kEncoderSilent = 7,
  kEncoderGlitch = 8,
  kEncoderReversed = 9,
  kEncoderChannel = 10,
  kHostSilent = 11,
  kForceSaturated = 12,
  kForceNegative = 13,
};
// "the encoder reads the disc turning backwards ...: swap ...": what happened and what to check,
// for a person at the rig; a 1.1 device's fault alone when the cause is unknown.
std::string fault_cause_text(std::uint8_t fault, std::uint8_t cause);
enum class ResetCause : std::uint8_t { kPowerOn = 0, kExternal = 1, kBrownOut = 2, kWatchdog = 3 };
std::string reset_cause_text(std::uint8_t cause);
inline constexpr std::uint8_t kHealthFactoryDefaults = 1u << 0;

inline constexpr std::size_t kIdentityBytes = 52;
inline constexpr std::size_t kStatusBytes = 16;     // 1.0 and 1.1; the least a reply holds
inline constexpr std::size_t kStatusBytes12 = 20;   // 1.2: a host asks for this many
inline constexpr std::size_t kCalibrationBytes = 12;
inline constexpr std::size_t kGeometryBytes = 8;
inline constexpr std::size_t kSerialBytes = 16;
inline constexpr std::size_t kPointBytes = 8;
inline constexpr std::size_t kMaxPointsPerRequest = 8;
inline constexpr std::size_t kPacketHeaderBytes = 4;
inline constexpr std::size_t kFrameBytes = 28;
inline constexpr std::size_t kMaxFramesPerPacket = 18;
inline constexpr std::size_t kMaxPacketBytes = 512;  // what the host reads each transfer with

struct Identity {
  std::uint16_t protocol_version = kProtocolVersion;
  std::uint16_t max_profile_points = 0;
  double max_speed_m_s = 0.0;
  double force_full_scale_N = 0.0;
  unsigned frame_rate_hz = 0;
  unsigned min_frame_rate_hz = 0;
  unsigned max_frame_rate_hz = 0;
  unsigned watchdog_timeout_ms = 0;
  std::string serial;    // at most 16 ASCII characters
  std::string firmware;  // at most 16 ASCII characters
};

struct DeviceStatus {
  std::uint16_t flags = 0;  // SensorFlag bits now
  Mode mode = Mode::kIdle;
  Fault fault = Fault::kNone;
  std::uint32_t next_sequence = 0;
  double speed_target_m_s = 0.0;
  std::uint16_t profile_points = 0;
  std::uint8_t refused_request = 0;
  std::uint8_t refusal = 0;
  // 1.2; a shorter reply leaves them so.
  FaultCause cause = FaultCause::kNone;
  ResetCause reset_cause = ResetCause::kPowerOn;
  std::uint8_t health = 0;
};

struct ForceCalibration {
  double normal_counts_per_N = 0.0;
  double tangential_counts_per_N = 0.0;
  double lever_factor = 0.0;
};

// What turns encoder counts into surface speed (PROTOCOL.md "Geometry").
struct Geometry {
  double counts_per_revolution = 0.0;
  double track_radius_m = 0.0;
};

// "1.0": how errors name a protocol version.
std::string version_text(std::uint16_t version);

// Why a serial cannot be sent by SET_SERIAL (empty, longer than 16, a byte outside 0x21..0x7E), or
// empty when it can: one rule for the host's check and the emulated device's refusal.
std::string serial_problem(const std::string& serial);

// Encoders give the exact bytes of PROTOCOL.md; decoders throw UsbRigError naming the layout and
// what was wrong (too short a reply, an unknown major version is the driver's call, not theirs).
std::array<std::uint8_t, kIdentityBytes> encode_identity(const Identity& identity);
Identity decode_identity(std::span<const std::uint8_t> bytes);
// 1.2's 20 bytes; a device of an older version sends the first 16.
std::array<std::uint8_t, kStatusBytes12> encode_status(const DeviceStatus& status);
DeviceStatus decode_status(std::span<const std::uint8_t> bytes);
std::array<std::uint8_t, kCalibrationBytes> encode_calibration(const ForceCalibration& calibration);
ForceCalibration decode_calibration(std::span<const std::uint8_t> bytes);
std::array<std::uint8_t, kGeometryBytes> encode_geometry(const Geometry& geometry);
Geometry decode_geometry(std::span<const std::uint8_t> bytes);
// SET_SERIAL's 16 bytes; throws UsbRigError with serial_problem's reason.
std::array<std::uint8_t, kSerialBytes> encode_serial(const std::string& serial);
// The text before the padding, as sent (not checked: the device checks).
std::string decode_serial(std::span<const std::uint8_t> bytes);
std::array<std::uint8_t, 4> encode_speed(double speed_m_s);
double decode_speed(std::span<const std::uint8_t> bytes);

// Profile points: time kept to the millisecond (rounded to nearest), speed in mm/s as f32.
std::vector<std::uint8_t> encode_points(std::span<const ProfilePoint> points);
std::vector<ProfilePoint> decode_points(std::span<const std::uint8_t> bytes);

// A frame packet. The decoder runs on the event thread: it neither allocates nor throws, and says
// what was wrong in `error` (a static string) when the packet is malformed (then `frames` is 0).
struct PacketDecode {
  std::size_t frames = 0;
  const char* error = nullptr;
};
PacketDecode decode_frame_packet(std::span<const std::uint8_t> packet,
                                 std::span<SensorFrame, kMaxFramesPerPacket> out) noexcept;
// 1..18 frames into one packet (for the emulated device and the tests).
std::vector<std::uint8_t> encode_frame_packet(std::span<const SensorFrame> frames);

}  // namespace nibrig::rig::usb
