#include "rig/pen/pen_rig_load.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <span>
#include <thread>

#include "rig/pen/pen_calibration.hpp"
#include "rig/pen/pen_clock.hpp"
#include "rig/sensor_frame.hpp"
#include "rig/usb/usb_rig_controller.hpp"

namespace nibrig::rig::pen {

RigLoadReader::RigLoadReader(const std::string& serial) {
  usb::UsbRigController::Options options;
  options.serial = serial;
  rig_ = std::make_unique<usb::UsbRigController>(options);
}

RigLoadReader::~RigLoadReader() = default;

std::string RigLoadReader::serial() const { return rig_->identity().serial; }

void RigLoadReader::drain() {
  std::array<SensorFrame, 512> block;
  while (const std::size_t n = rig_->read_frames(block)) {
    for (std::size_t i = 0; i < n; ++i) {
      const double device_s = 1e-6 * static_cast<double>(block[i].device_time_us);
      clock_.add(device_s, 1e-9 * static_cast<double>(block[i].host_ns));
      recent_.push_back({device_s, block[i].normal_force_N});
    }
  }
}

double RigLoadReader::load_n(double now_s, double window_s) {
  const double give_up = pen_clock_now_s() + kArrivalWaitS;
  while (true) {
    drain();
    if (clock_.ready() && !recent_.empty() && clock_.host_time(recent_.back().device_s) >= now_s) break;
    if (pen_clock_now_s() > give_up) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (!rig_->status().connected) throw PenCalibrationRefusal("the rig " + serial() + " is unplugged: plug it back in");
  if (!clock_.ready()) throw PenCalibrationRefusal("the rig has sent too few frames yet: is it streaming?");
  const double from = clock_.device_time(now_s - window_s), to = clock_.device_time(now_s);
  // Frames older than the window are of no later hold either: each hold is newer than the last.
  while (!recent_.empty() && recent_.front().device_s < from) recent_.pop_front();
  double sum = 0.0, sum2 = 0.0;
  std::size_t n = 0;
  for (const auto& r : recent_) {
    if (r.device_s > to) break;
    sum += r.force_n;
    sum2 += r.force_n * r.force_n;
    ++n;
  }
  char text[200];
  if (n == 0) {
    std::snprintf(text, sizeof text, "the rig sent no frame sampled in the last %.2f s: is it streaming?", window_s);
    throw PenCalibrationRefusal(text);
  }
  const double mean = sum / static_cast<double>(n);
  const double sd = std::sqrt(std::max(0.0, sum2 / static_cast<double>(n) - mean * mean));
  if (mean < kMinimumLoadN) {
    std::snprintf(text, sizeof text, "the rig's sensor reads %.3f N: press the pen on it (at least %.2f N)", mean,
                  kMinimumLoadN);
    throw PenCalibrationRefusal(text);
  }
  if (sd > kSteadyRelativeSd * mean) {
    std::snprintf(text, sizeof text,
                  "the rig's load was not steady: %.3f N, sd %.3f N over the last %.2f s (at most %.0f %%); hold "
                  "still",
                  mean, sd, window_s, 100.0 * kSteadyRelativeSd);
    throw PenCalibrationRefusal(text);
  }
  return mean;
}

}  // namespace nibrig::rig::pen
