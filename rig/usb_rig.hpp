// The real rig: the USB controller (rig/usb, PROTOCOL.md) for speed and forces, the accelerometer on
// an audio input (rig/accelerometer_input.hpp), and the time base that puts both on one timeline.
// The acceleration's sample clock is the master: the session's frame k belongs with acceleration
// sample k·r (r = acceleration rate / frame rate). Its host time comes from the audio callbacks'
// stamps; the controller's frames, stamped on the device's own microsecond clock, are mapped onto
// the host clock by the lower envelope of their arrival times (rig/clock_fit.hpp) and interpolated
// at that host time. So a tap felt by the force sensor and by the accelerometer lands on the same
// instant of the session, however the two clocks drift or the USB batches its packets.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "rig/accelerometer_input.hpp"
#include "rig/clock_fit.hpp"
#include "rig/rig.hpp"
#include "rig/usb/usb_rig_controller.hpp"
#include "rt/reference_load.hpp"

namespace nibrig::rig {

struct UsbRigSettings {
  usb::UsbRigController::Options controller;  // its serial: empty = the only one on the bus
  AccelerometerSettings accelerometer;
  double normal_load_N =
      rt::kReferenceNormalForce;  // the arm's load as mounted (the frames carry the measured force)
};

class UsbRig final : public Rig {
 public:
  // Opens the controller and the accelerometer input. Throws usb::UsbRigError (a missing controller
  // names what is on the bus) or playback::DeviceError (a missing audio device names what exists).
  explicit UsbRig(const UsbRigSettings& settings);
  ~UsbRig() override;  // removes the frame listener before the controller goes

  const RigDescription& description() const override { return description_; }
  // Uploads the profile (refused beyond the motor, with its range) and starts it.
  void start(const SpeedProfile& profile) override;
  bool read(RigData& into, std::chrono::milliseconds wait) override;
  void stop() override;
  RigHealth health() const override;
  void set_frame_listener(const FrameListener* listener) override {
    controller_->set_frame_listener(listener);
  }

 private:
  struct AudioBlock {
    std::uint64_t first = 0;  // index in the capture's timeline (from start)
    double host_s = 0.0;      // when its first sample was taken
  };
  void drain_frames();
  void drain_acceleration();
  double host_time_of_sample(double n) const;  // n counted from the timeline's start
  bool next_frame(SensorFrame& out);

  UsbRigSettings settings_;
  std::unique_ptr<usb::UsbRigController> controller_;
  std::unique_ptr<AccelerometerInput> input_;
  RigDescription description_;
  ClockFit usb_clock_;
  std::deque<SensorFrame> received_;  // device frames not yet passed, by device time
  std::vector<SensorFrame> frame_buffer_;
  std::vector<float> acceleration_;   // captured since start, not yet delivered
  std::uint64_t acceleration_first_ = 0;  // timeline index of acceleration_[0]
  std::uint64_t base_index_ = 0;          // the input's index of the timeline's first sample
  std::deque<AudioBlock> blocks_;
  double samples_per_frame_ = 48.0;
  std::uint64_t frames_made_ = 0, frames_total_ = 0;
  bool started_ = false, stopped_ = false;
  RigHealth health_;
};

}  // namespace nibrig::rig
