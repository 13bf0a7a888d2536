// A pen's calibration on the rig instead of a kitchen scale: the pen pressed on the turntable rig's
// normal-force sensor, each hold's load the mean of the rig's frames sampled in the same window as
// the pen's pressure (pen_calibration.hpp). The frames are placed in host time by the device's own
// clock (rig/clock_fit.hpp), not by when their packets arrived, so a late packet cannot carry the
// last hold's load into this one.
#pragma once

#include <deque>
#include <memory>
#include <string>

#include "rig/clock_fit.hpp"

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

  // The mean normal force (N) of the frames sampled within [now_s − window_s, now_s] (host
  // CLOCK_MONOTONIC seconds, the pen's clock), once a frame sampled at now_s or later has come (or
  // kArrivalWait has passed). Throws PenCalibrationRefusal when the rig is unplugged or sent no
  // frame in the window, when the load is under kMinimumLoadN, or when it was not steady (its
  // standard deviation over kSteadyRelativeSd of the mean, the pen's own limit).
  double load_n(double now_s, double window_s);
  std::string serial() const;

  // Below this the sensor reads no pen on it: its noise, and a zero that drifts.
  static constexpr double kMinimumLoadN = 0.01;
  static constexpr double kSteadyRelativeSd = 0.05;
  // USB packets carry 8 frames at 1 kHz: the window's last frames arrive within a few ms; this
  // covers a loaded host.
  static constexpr double kArrivalWaitS = 0.25;

 private:
  struct Reading {
    double device_s;
    double force_n;
  };
  void drain();

  std::unique_ptr<usb::UsbRigController> rig_;
  ClockFit clock_;
  std::deque<Reading> recent_;
};

}  // namespace nibrig::rig::pen
