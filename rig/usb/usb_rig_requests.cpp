// The rig controller's control requests (PROTOCOL.md "Control requests"), from the caller's
// thread: the host-side range checks that give the clearest message, then the request itself.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rig/usb/usb_rig_controller.hpp"

namespace nibrig::rig::usb {
namespace {

std::string mm_s(double speed_m_s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f mm/s", speed_m_s * 1000.0);
  return text;
}

}  // namespace

Identity UsbRigController::identity() const {
  std::lock_guard lock(device_mutex_);
  return identity_;
}

Identity UsbRigController::identify() {
  return with_channel([&](ControlChannel& c) {
    identity_ = c.identify();
    return identity_;
  });
}

// A start clears the device's fault (PROTOCOL.md "Status"): the one it had is no longer news.
void UsbRigController::clear_device_fault() {
  std::lock_guard lock(fault_mutex_);
  device_fault_.clear();
}

void UsbRigController::set_speed(double speed_m_s) {
  const Identity id = identity();
  if (!(speed_m_s >= 0.0 && speed_m_s <= id.max_speed_m_s)) {
    throw UsbRigError("speed " + mm_s(speed_m_s) + " is outside what the rig controller " + serial_ +
                      " runs: 0 to " + mm_s(id.max_speed_m_s));
  }
  clear_device_fault();
  with_channel([&](ControlChannel& c) { c.out(Request::kSetSpeed, 0, 0, encode_speed(speed_m_s)); });
}

void UsbRigController::upload_profile(const SpeedProfile& profile) {
  const Identity id = identity();
  if (profile.max_speed_m_s() > id.max_speed_m_s) {
    throw UsbRigError("profile '" + profile.description() + "' reaches " +
                      mm_s(profile.max_speed_m_s()) + "; the rig controller " + serial_ +
                      " runs 0 to " + mm_s(id.max_speed_m_s));
  }
  const auto& points = profile.points();
  if (points.size() > id.max_profile_points) {
    throw UsbRigError("profile '" + profile.description() + "' has " + std::to_string(points.size()) +
                      " points; the rig controller " + serial_ + " holds at most " +
                      std::to_string(id.max_profile_points));
  }
  with_channel([&](ControlChannel& c) {
    c.out(Request::kProfileBegin, static_cast<std::uint16_t>(points.size()), 0);
    for (std::size_t first = 0; first < points.size(); first += kMaxPointsPerRequest) {
      const std::size_t n = std::min(kMaxPointsPerRequest, points.size() - first);
      c.out(Request::kProfileWrite, 0, static_cast<std::uint16_t>(first),
            encode_points(std::span<const ProfilePoint>(points).subspan(first, n)));
    }
    c.out(Request::kProfileEnd, 0, 0);
  });
}

std::vector<ProfilePoint> UsbRigController::read_profile() {
  return with_channel([&](ControlChannel& c) {
    const std::size_t count = c.status().profile_points;
    std::vector<ProfilePoint> points;
    for (std::size_t first = 0; first < count; first += kMaxPointsPerRequest) {
      const auto n = static_cast<std::uint16_t>(std::min(kMaxPointsPerRequest, count - first) * kPointBytes);
      const auto chunk = decode_points(c.in(Request::kProfileRead, 0, static_cast<std::uint16_t>(first), n, n));
      points.insert(points.end(), chunk.begin(), chunk.end());
    }
    return points;
  });
}

void UsbRigController::start_profile() {
  clear_device_fault();
  with_channel([&](ControlChannel& c) { c.out(Request::kStartProfile, 0, 0); });
}

void UsbRigController::stop() {
  with_channel([&](ControlChannel& c) { c.out(Request::kStop, 0, 0); });
}

void UsbRigController::zero_force() {
  with_channel([&](ControlChannel& c) { c.out(Request::kZeroForce, 0, 0); });
}

void UsbRigController::set_frame_rate(unsigned frames_per_second) {
  const Identity id = identity();
  if (frames_per_second < id.min_frame_rate_hz || frames_per_second > id.max_frame_rate_hz) {
    throw UsbRigError("frame rate " + std::to_string(frames_per_second) + " Hz is outside what the rig controller " +
                      serial_ + " samples: " + std::to_string(id.min_frame_rate_hz) + " to " +
                      std::to_string(id.max_frame_rate_hz) + " Hz");
  }
  with_channel([&](ControlChannel& c) {
    c.out(Request::kSetFrameRate, static_cast<std::uint16_t>(frames_per_second), 0);
    identity_.frame_rate_hz = frames_per_second;
  });
}

DeviceStatus UsbRigController::device_status() {
  return with_channel([&](ControlChannel& c) { return c.status(); });
}

ForceCalibration UsbRigController::calibration() {
  return with_channel([&](ControlChannel& c) {
    return decode_calibration(c.in(Request::kGetCalibration, 0, 0, kCalibrationBytes, kCalibrationBytes));
  });
}

void UsbRigController::set_calibration(const ForceCalibration& calibration) {
  with_channel([&](ControlChannel& c) {
    c.out(Request::kSetCalibration, 0, 0, encode_calibration(calibration));
  });
}

void UsbRigController::require_version(Request request, std::uint16_t version) const {
  const Identity id = identity();
  if (id.protocol_version < version) {
    throw UsbRigError("the rig controller " + serial_ + " speaks protocol " + version_text(id.protocol_version) +
                      "; " + request_name(static_cast<std::uint8_t>(request)) + " needs " +
                      version_text(version) + " (`nibrig rig flash` updates its firmware)");
  }
}

Geometry UsbRigController::geometry() {
  require_version(Request::kGetGeometry, kGeometryVersion);
  return with_channel([&](ControlChannel& c) {
    return decode_geometry(c.in(Request::kGetGeometry, 0, 0, kGeometryBytes, kGeometryBytes));
  });
}

void UsbRigController::set_geometry(const Geometry& geometry) {
  require_version(Request::kSetGeometry, kGeometryVersion);
  if (!(std::isfinite(geometry.counts_per_revolution) && geometry.counts_per_revolution > 0.0)) {
    throw UsbRigError("encoder counts per revolution " + std::to_string(geometry.counts_per_revolution) +
                      ": the rig controller " + serial_ + " needs a finite number above 0");
  }
  if (!(std::isfinite(geometry.track_radius_m) && geometry.track_radius_m > 0.0)) {
    throw UsbRigError("track radius " + std::to_string(geometry.track_radius_m * 1000.0) +
                      " mm: the rig controller " + serial_ + " needs a finite radius above 0");
  }
  with_channel([&](ControlChannel& c) { c.out(Request::kSetGeometry, 0, 0, encode_geometry(geometry)); });
}

void UsbRigController::set_serial(const std::string& serial) {
  require_version(Request::kSetSerial, kGeometryVersion);
  const auto bytes = encode_serial(serial);
  with_channel([&](ControlChannel& c) {
    c.out(Request::kSetSerial, 0, 0, bytes);
    identity_ = c.identify();
  });
}

void UsbRigController::enter_bootloader() {
  require_version(Request::kEnterBootloader, kGeometryVersion);
  with_channel([&](ControlChannel& c) { c.out(Request::kEnterBootloader, kBootloaderKey, 0); });
}

}  // namespace nibrig::rig::usb
