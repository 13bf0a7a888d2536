#include "rig/pen/pen_rig_load.hpp"

#include <array>
#include <cstdio>
#include <span>

#include "rig/pen/pen_calibration.hpp"
#include "rig/usb/usb_rig_controller.hpp"

namespace nibrig::rig::pen {

RigLoadReader::RigLoadReader(const std::string& serial) {
  usb::UsbRigController::Options options;
  options.serial = serial;
  rig_ = std::make_unique<usb::UsbRigController>(options);
}

RigLoadReader::~RigLoadReader() = default;

std::string RigLoadReader::serial() const { return rig_->identity().serial; }

double RigLoadReader::load_n(double now_s, double window_s) {
  std::array<SensorFrame, 512> block;
  while (const std::size_t n = rig_->read_frames(block)) recent_.insert(recent_.end(), block.begin(), block.begin() + static_cast<std::ptrdiff_t>(n));
  const auto from_ns = static_cast<std::int64_t>((now_s - window_s) * 1e9);
  const auto to_ns = static_cast<std::int64_t>(now_s * 1e9);
  // Frames older than the window are of no later hold either: each hold is newer than the last.
  while (!recent_.empty() && recent_.front().host_ns < from_ns) recent_.pop_front();
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto& f : recent_) {
    if (f.host_ns > to_ns) break;
    sum += f.normal_force_N;
    ++n;
  }
  if (n == 0) throw PenCalibrationRefusal("the rig sent no frame in the last " + std::to_string(window_s) + " s: is it streaming?");
  const double load = sum / static_cast<double>(n);
  if (load < kMinimumRigLoadN) {
    char text[160];
    std::snprintf(text, sizeof text, "the rig's sensor reads %.3f N: press the pen on it (at least %.2f N)", load,
                  kMinimumRigLoadN);
    throw PenCalibrationRefusal(text);
  }
  return load;
}

}  // namespace nibrig::rig::pen
