// The emulated rig's answers to PROTOCOL.md's control requests, with the checks the document
// asks of a device (lengths, ranges, order), so that the driver's error paths meet a real refusal.
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "tests/rig/usb/emulated_rig.hpp"

namespace nibrig::rig::usb::testing {

EmulatedRig::Reply EmulatedRig::refuse(std::uint8_t request, Refusal why) {
  refused_request_ = request;
  refusal_ = static_cast<std::uint8_t>(why);
  return {true, false, {}};
}

// PROTOCOL.md's control requests, checked as the document says a device checks them.
EmulatedRig::Reply EmulatedRig::control(const std::uint8_t* setup, const std::uint8_t* data) {
  const std::uint8_t type = setup[0];
  const std::uint8_t request = setup[1];
  const unsigned value = setup[2] | (setup[3] << 8);
  const unsigned index = setup[4] | (setup[5] << 8);
  const unsigned length = setup[6] | (setup[7] << 8);
  if (ignore_next_) {
    ignore_next_ = false;
    return {false, true, {}};
  }
  if (refuse_next_ && refuse_next_->first == request) {
    const Refusal why = refuse_next_->second;
    refuse_next_.reset();
    return refuse(request, why);
  }
  const bool in = type == kRequestTypeIn;
  if (type != kRequestTypeIn && type != kRequestTypeOut) return refuse(request, Refusal::kUnknown);
  const std::span<const std::uint8_t> payload(data, in ? 0 : length);
  auto out_length = [&](unsigned n) { return !in && length == n; };
  switch (static_cast<Request>(request)) {
    case Request::kIdentify: {
      if (!in || length < kIdentityBytes) return refuse(request, Refusal::kLength);
      Identity id;
      id.protocol_version = config_.protocol_version;
      id.max_profile_points = config_.max_profile_points;
      id.max_speed_m_s = config_.max_speed_m_s;
      id.force_full_scale_N = kForceFullScaleN;
      id.frame_rate_hz = frame_rate_hz_;
      id.min_frame_rate_hz = 500;
      id.max_frame_rate_hz = 4000;
      id.watchdog_timeout_ms = 500;
      id.serial = config_.serial;
      id.firmware = "emulated-" + version_text(config_.protocol_version);
      const auto bytes = encode_identity(id);
      return {false, false, {bytes.begin(), bytes.end()}};
    }
    case Request::kGetStatus: {
      if (!in || length < kStatusBytes) return refuse(request, Refusal::kLength);
      const DeviceStatus s{flags_, mode_, fault_, sequence_, target_m_s_,
                           static_cast<std::uint16_t>(profile_ ? profile_->points().size() : 0),
                           refused_request_, refusal_};
      const auto bytes = encode_status(s);
      // A device before 1.2 sends the 16 bytes of its version.
      const std::size_t sent = config_.protocol_version >= kFaultCauseVersion ? kStatusBytes12 : kStatusBytes;
      return {false, false, {bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(sent)}};
    }
    case Request::kSetStreaming:
      if (!out_length(0)) return refuse(request, Refusal::kLength);
      if (value > 1) return refuse(request, Refusal::kRange);
      if (value == 1 && !streaming_) fifo_.clear();
      streaming_ = value == 1;
      return {};
    case Request::kSetSpeed: {
      if (!out_length(4)) return refuse(request, Refusal::kLength);
      const double speed = decode_speed(payload);
      if (!(speed >= 0.0 && speed <= config_.max_speed_m_s * (1.0 + 1e-6))) return refuse(request, Refusal::kRange);
      target_m_s_ = speed;
      mode_ = Mode::kSpeed;
      fault_ = Fault::kNone;
      flags_ &= static_cast<std::uint16_t>(~kWatchdogStopped);
      return {};
    }
    case Request::kStartProfile:
      if (!out_length(0)) return refuse(request, Refusal::kLength);
      if (!profile_) return refuse(request, Refusal::kOrder);
      mode_ = Mode::kProfile;
      profile_start_us_ = clock_us();
      fault_ = Fault::kNone;
      flags_ &= static_cast<std::uint16_t>(~kWatchdogStopped);
      return {};
    case Request::kStop:
      if (!out_length(0)) return refuse(request, Refusal::kLength);
      mode_ = Mode::kIdle;
      target_m_s_ = 0.0;
      return {};
    case Request::kProfileBegin:
      if (!out_length(0)) return refuse(request, Refusal::kLength);
      if (value < 1 || value > config_.max_profile_points) return refuse(request, Refusal::kRange);
      if (mode_ == Mode::kProfile || mode_ == Mode::kProfileDone) mode_ = Mode::kIdle;
      profile_.reset();
      upload_.clear();
      upload_expected_ = static_cast<std::uint16_t>(value);
      return {};
    case Request::kProfileWrite: {
      if (in || length == 0 || length % kPointBytes != 0 || length / kPointBytes > kMaxPointsPerRequest) {
        return refuse(request, Refusal::kLength);
      }
      if (index != upload_.size()) return refuse(request, Refusal::kOrder);
      const auto points = decode_points(payload);
      if (upload_.size() + points.size() > upload_expected_) return refuse(request, Refusal::kRange);
      upload_.insert(upload_.end(), points.begin(), points.end());
      return {};
    }
    case Request::kProfileEnd:
      if (!out_length(0)) return refuse(request, Refusal::kLength);
      if (upload_expected_ == 0 || upload_.size() != upload_expected_) return refuse(request, Refusal::kOrder);
      try {
        SpeedProfile profile("uploaded", upload_);
        if (profile.max_speed_m_s() > config_.max_speed_m_s * (1.0 + 1e-6)) return refuse(request, Refusal::kRange);
        profile_ = std::move(profile);
      } catch (const std::invalid_argument&) {
        return refuse(request, Refusal::kRange);
      }
      return {};
    case Request::kProfileRead: {
      if (!in || length == 0 || length % kPointBytes != 0 || length / kPointBytes > kMaxPointsPerRequest) {
        return refuse(request, Refusal::kLength);
      }
      const std::size_t count = length / kPointBytes;
      if (!profile_ || index + count > profile_->points().size()) return refuse(request, Refusal::kRange);
      return {false, false,
              encode_points(std::span<const ProfilePoint>(profile_->points()).subspan(index, count))};
    }
    case Request::kZeroForce:
      if (!out_length(0)) return refuse(request, Refusal::kLength);
      if (arm_load_) {  // the sensor model: what the bridges read now is their zero
        normal_zero_counts_ = kNormalOffsetCounts + kTrueNormalCountsPerN * arm_load_->normal_N;
        tangential_zero_counts_ = kTangentialOffsetCounts + kTrueTangentialCountsPerN * arm_load_->tangential_N;
        apply_arm_model();
      } else {
        force_zero_N_ = kLoadN;  // the tip is taken to be lifted: what it reads now is the zero
      }
      return {};
    case Request::kSetFrameRate:
      if (!out_length(0)) return refuse(request, Refusal::kLength);
      if (value < 500 || value > 4000) return refuse(request, Refusal::kRange);
      frame_rate_hz_ = value;
      return {};
    case Request::kGetCalibration: {
      if (!in || length < kCalibrationBytes) return refuse(request, Refusal::kLength);
      const auto bytes = encode_calibration(calibration_);
      return {false, false, {bytes.begin(), bytes.end()}};
    }
    case Request::kSetCalibration: {
      if (!out_length(kCalibrationBytes)) return refuse(request, Refusal::kLength);
      const ForceCalibration c = decode_calibration(payload);
      for (double v : {c.normal_counts_per_N, c.tangential_counts_per_N, c.lever_factor}) {
        if (!(std::isfinite(v) && v > 0.0)) return refuse(request, Refusal::kRange);
      }
      calibration_ = c;
      apply_arm_model();
      return {};
    }
    case Request::kGetGeometry:
    case Request::kSetGeometry:
    case Request::kSetSerial:
    case Request::kEnterBootloader:
      if (config_.protocol_version < kGeometryVersion) break;  // a 1.0 device: unknown
      return control_1_1(request, value, in, length, payload);
  }
  return refuse(request, Refusal::kUnknown);
}

// PROTOCOL.md "Version 1.1": geometry, serial, bootloader.
EmulatedRig::Reply EmulatedRig::control_1_1(std::uint8_t request, unsigned value, bool in, unsigned length,
                                            std::span<const std::uint8_t> payload) {
  switch (static_cast<Request>(request)) {
    case Request::kGetGeometry: {
      if (!in || length < kGeometryBytes) return refuse(request, Refusal::kLength);
      const auto bytes = encode_geometry(geometry_);
      return {false, false, {bytes.begin(), bytes.end()}};
    }
    case Request::kSetGeometry: {
      if (in || length != kGeometryBytes) return refuse(request, Refusal::kLength);
      const Geometry g = decode_geometry(payload);
      for (double v : {g.counts_per_revolution, g.track_radius_m}) {
        if (!(std::isfinite(v) && v > 0.0)) return refuse(request, Refusal::kRange);
      }
      geometry_ = g;
      return {};
    }
    case Request::kSetSerial: {
      if (in || length != kSerialBytes) return refuse(request, Refusal::kLength);
      const std::string serial = decode_serial(payload);
      if (!serial_problem(serial).empty()) return refuse(request, Refusal::kRange);
      config_.serial = serial;  // IDENTIFY reports it from now on
      return {};
    }
    case Request::kEnterBootloader:
      if (in || length != 0) return refuse(request, Refusal::kLength);
      if (value != kBootloaderKey) return refuse(request, Refusal::kRange);
      if (mode_ == Mode::kSpeed || mode_ == Mode::kProfile) return refuse(request, Refusal::kOrder);
      // The real board now leaves the bus; here the test unplugs it, as it plays the hardware.
      entered_bootloader_ = true;
      return {};
    default:
      return refuse(request, Refusal::kUnknown);
  }
}

// The device's formula (PROTOCOL.md "Force sensor") over the bridges' counts for the load placed.
void EmulatedRig::apply_arm_model() {
  if (!arm_load_) return;
  const double normal_counts = kNormalOffsetCounts + kTrueNormalCountsPerN * arm_load_->normal_N;
  const double tangential_counts = kTangentialOffsetCounts + kTrueTangentialCountsPerN * arm_load_->tangential_N;
  const double normal = (normal_counts - normal_zero_counts_) / calibration_.normal_counts_per_N * calibration_.lever_factor;
  const double tangential =
      (tangential_counts - tangential_zero_counts_) / calibration_.tangential_counts_per_N * calibration_.lever_factor;
  const bool tangential_only = arm_load_->normal_N == 0.0 && arm_load_->tangential_N != 0.0;
  force_zero_N_ = kLoadN - (tangential_only ? tangential / 0.3 : normal);
}

void EmulatedRig::place_on_arm(double normal_N, double tangential_N) {
  std::lock_guard lock(mutex_);
  arm_load_ = ArmLoad{normal_N, tangential_N};
  apply_arm_model();
}

Geometry EmulatedRig::geometry() const {
  std::lock_guard lock(mutex_);
  return geometry_;
}

bool EmulatedRig::entered_bootloader() const {
  std::lock_guard lock(mutex_);
  return entered_bootloader_;
}

}  // namespace nibrig::rig::usb::testing
