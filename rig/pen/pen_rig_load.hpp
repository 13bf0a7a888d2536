// A pen's calibration on the rig instead of a kitchen scale: the pen pressed on the turntable rig's
// normal-force sensor, each hold's load the mean of the rig's frames over the same window as the
// pen's pressure (pen_calibration.hpp), both on the host's monotonic clock.
#pragma once

#include <deque>
#include <memory>
#include <string>

#include "rig/sensor_frame.hpp"

namespace nibrig::rig::usb {
class UsbRigController;
}

namespace nibrig::rig::pen {

class RigLoadReader {
 public:
  // Opens the USB rig controller (`serial`, or the only one) and streams its frames. Throws what
  // usb::UsbRigController throws.
  explicit RigLoadReader(const std::string& serial);
  ~RigLoadReader();
  RigLoadReader(const RigLoadReader&) = delete;
  RigLoadReader& operator=(const RigLoadReader&) = delete;

  // The mean normal force (N) of the frames the host received within [now_s - window_s, now_s]
  // (CLOCK_MONOTONIC, the frames' host stamps). Throws PenCalibrationRefusal when none came in the
  // window (the rig stopped streaming) or the load is under kMinimumRigLoadN.
  double load_n(double now_s, double window_s);
  std::string serial() const;

  // Below this the sensor reads no pen on it: its noise, and a zero that drifts.
  static constexpr double kMinimumRigLoadN = 0.01;

 private:
  std::unique_ptr<usb::UsbRigController> rig_;
  std::deque<SensorFrame> recent_;
};

}  // namespace nibrig::rig::pen
