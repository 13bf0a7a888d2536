// The rig controller's wire format (rig/PROTOCOL.md) as plain bytes in and out: request numbers,
// reply layouts and frame packets, with no libusb in sight, so that the driver and the tests'
// emulated device share one definition and each layout is tested against hand-built bytes. The
// numbers are the firmware's own (rig/firmware/rig_protocol.h), named here for C++.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rig/firmware/rig_protocol.h"
#include "rig/sensor_frame.hpp"
#include "rig/speed_profile.hpp"

namespace nibrig::rig::usb {

inline constexpr std::uint16_t kVendorId = RIG_USB_VENDOR_ID;
inline constexpr std::uint16_t kProductId = RIG_USB_PRODUCT_ID;
inline constexpr int kInterface = 0;
inline constexpr std::uint8_t kStreamEndpoint = RIG_STREAM_ENDPOINT;
inline constexpr std::uint8_t kRequestTypeIn = RIG_REQUEST_TYPE_IN;
inline constexpr std::uint8_t kRequestTypeOut = RIG_REQUEST_TYPE_OUT;
inline constexpr std::uint16_t kProtocolVersion = RIG_PROTOCOL_VERSION;
inline constexpr std::uint16_t kGeometryVersion = RIG_GEOMETRY_VERSION;
inline constexpr std::uint16_t kFaultCauseVersion = RIG_FAULT_CAUSE_VERSION;
inline constexpr std::uint16_t kBootloaderKey = RIG_BOOTLOADER_KEY;

enum class Request : std::uint8_t {
  kIdentify = RIG_IDENTIFY,
  kGetStatus = RIG_GET_STATUS,
  kSetStreaming = RIG_SET_STREAMING,
  kSetSpeed = RIG_SET_SPEED,
  kStartProfile = RIG_START_PROFILE,
  kStop = RIG_STOP,
  kProfileBegin = RIG_PROFILE_BEGIN,
  kProfileWrite = RIG_PROFILE_WRITE,
  kProfileEnd = RIG_PROFILE_END,
  kProfileRead = RIG_PROFILE_READ,
  kZeroForce = RIG_ZERO_FORCE,
  kSetFrameRate = RIG_SET_FRAME_RATE,
  kGetCalibration = RIG_GET_CALIBRATION,
  kSetCalibration = RIG_SET_CALIBRATION,
  kGetGeometry = RIG_GET_GEOMETRY,
  kSetGeometry = RIG_SET_GEOMETRY,
  kSetSerial = RIG_SET_SERIAL,
  kEnterBootloader = RIG_ENTER_BOOTLOADER,
};
// "IDENTIFY (0x01)": how errors name a request.
std::string request_name(std::uint8_t request);

// PROTOCOL.md "Errors": why the device refused a request.
enum class Refusal : std::uint8_t {
  kNone = RIG_REFUSE_NONE,
  kUnknown = RIG_REFUSE_UNKNOWN,
  kLength = RIG_REFUSE_LENGTH,
  kRange = RIG_REFUSE_RANGE,
  kOrder = RIG_REFUSE_ORDER
};
std::string refusal_text(std::uint8_t refusal);

enum class Mode : std::uint8_t {
  kIdle = RIG_IDLE,
  kSpeed = RIG_SPEED,
  kProfile = RIG_PROFILE,
  kProfileDone = RIG_PROFILE_DONE
};
enum class Fault : std::uint8_t {
  kNone = RIG_FAULT_NONE,
  kMotor = RIG_FAULT_MOTOR,
  kEncoder = RIG_FAULT_ENCODER,
  kWatchdog = RIG_FAULT_WATCHDOG,
  kForce = RIG_FAULT_FORCE
};
std::string fault_text(std::uint8_t fault);
// PROTOCOL.md "Fault causes" (1.2): why the device stopped the motor.
enum class FaultCause : std::uint8_t {
  kNone = RIG_CAUSE_NONE,
  kStall = RIG_CAUSE_STALL,
  kOverCurrent = RIG_CAUSE_OVERCURRENT,
  kDriver = RIG_CAUSE_DRIVER,
  kSupply = RIG_CAUSE_SUPPLY,
  kOverSpeed = RIG_CAUSE_OVERSPEED,
  kSlip = RIG_CAUSE_SLIP,
  kEncoderSilent = RIG_CAUSE_ENCODER_SILENT,
  kEncoderGlitch = RIG_CAUSE_ENCODER_GLITCH,
  kEncoderReversed = RIG_CAUSE_ENCODER_REVERSED,
  kEncoderChannel = RIG_CAUSE_ENCODER_CHANNEL,
  kHostSilent = RIG_CAUSE_HOST_SILENT,
  kForceSaturated = RIG_CAUSE_FORCE_SATURATED,
  kForceNegative = RIG_CAUSE_FORCE_NEGATIVE,
};
// "the encoder reads the disc turning backwards ...: swap ...": what happened and what to check,
// for a person at the rig; a 1.1 device's fault alone when the cause is unknown.
std::string fault_cause_text(std::uint8_t fault, std::uint8_t cause);
enum class ResetCause : std::uint8_t {
  kPowerOn = RIG_RESET_POWER_ON,
  kExternal = RIG_RESET_EXTERNAL,
  kBrownOut = RIG_RESET_BROWN_OUT,
  kWatchdog = RIG_RESET_WATCHDOG
};
std::string reset_cause_text(std::uint8_t cause);
inline constexpr std::uint8_t kHealthFactoryDefaults = RIG_HEALTH_FACTORY_DEFAULTS;

inline constexpr std::size_t kIdentityBytes = RIG_IDENTITY_BYTES;
inline constexpr std::size_t kStatusBytes = RIG_STATUS_BYTES_1_0;  // the least a reply holds
inline constexpr std::size_t kStatusBytes12 = RIG_STATUS_BYTES;    // 1.2: a host asks for this many
inline constexpr std::size_t kCalibrationBytes = RIG_CALIBRATION_BYTES;
inline constexpr std::size_t kGeometryBytes = RIG_GEOMETRY_BYTES;
inline constexpr std::size_t kSerialBytes = RIG_SERIAL_BYTES;
inline constexpr std::size_t kPointBytes = RIG_POINT_BYTES;
inline constexpr std::size_t kMaxPointsPerRequest = RIG_MAX_POINTS_PER_REQUEST;
inline constexpr std::size_t kPacketHeaderBytes = RIG_PACKET_HEADER_BYTES;
inline constexpr std::size_t kFrameBytes = RIG_FRAME_BYTES;
inline constexpr std::size_t kMaxFramesPerPacket = RIG_MAX_FRAMES_PER_PACKET;
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
