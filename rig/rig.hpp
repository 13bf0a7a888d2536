// The turntable rig as every capture, comparison and face sees it, whatever is behind it: the USB
// controller with an accelerometer on an audio input, the simulated rig, or a recorded session
// replayed. A rig runs a speed profile and delivers two streams on one timeline that starts when
// the profile starts: sensor frames (speed and forces, frame k at k / frame_rate_hz) and
// acceleration (sample n at n / acceleration_rate_hz). A rig whose clocks differ (the USB
// controller's against the audio interface's) puts them on that timeline itself and says how well
// it managed (RigHealth::alignment_error_ms).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rig/sensor_frame.hpp"
#include "rig/speed_profile.hpp"
#include "rt/reference_load.hpp"

namespace nibrig::rig {

struct RigDescription {
  std::string kind;  // "simulated", "usb", "replay"
  std::string name;  // one line for people: "simulated rig: vero2 on office, seed 1"
  std::string tool, surface;  // what is mounted, when the rig knows it (simulated, replay)
  double frame_rate_hz = 1000.0;
  double acceleration_rate_hz = 48000.0;
  double max_speed_m_s = 0.0;    // the fastest the motor follows
  double normal_load_N = rt::kReferenceNormalForce;  // the arm's load
  // Calibration written into every session: acceleration samples × this = m/s²; the force sensor's
  // counts per newton and the arm's lever factor (the frames already carry newtons).
  double accelerometer_m_s2_per_unit = 1.0;
  double force_counts_per_N = 403.2;
  double lever_factor = 1.0;
  std::string acceleration_units = "m/s²";
};

// What a rig delivered since the last read, appended by read().
struct RigData {
  std::vector<SensorFrame> frames;
  std::vector<float> acceleration;  // in the rig's units (× accelerometer_m_s2_per_unit = m/s²)
  void clear() {
    frames.clear();
    acceleration.clear();
  }
};

struct RigHealth {
  std::uint64_t frames = 0;          // delivered
  std::uint64_t dropped_frames = 0;  // lost before delivery (sequence gaps)
  std::uint64_t saturated_frames = 0;
  std::uint64_t fault_frames = 0;
  std::uint64_t acceleration_samples = 0;
  double alignment_error_ms = 0.0;  // estimated error of the common timeline
  bool connected = true;
  std::string ended_because;  // empty while running
};

using FrameListener = std::function<void(const SensorFrame&)>;

class Rig {
 public:
  virtual ~Rig() = default;
  virtual const RigDescription& description() const = 0;
  // Starts the profile. Throws std::invalid_argument saying the motor's range when the profile
  // asks for more, std::logic_error when already started.
  virtual void start(const SpeedProfile& profile) = 0;
  // Appends to `into` everything that arrived, waiting at most `wait` for something to arrive.
  // Returns false once the run is over (profile finished, replay ended, device gone) and nothing
  // more will come; RigHealth::ended_because then says why.
  virtual bool read(RigData& into, std::chrono::milliseconds wait) = 0;
  // Stops the motor (idempotent); read() then returns what is left and false.
  virtual void stop() = 0;
  virtual RigHealth health() const = 0;
  // Called with each frame as soon as the rig has it, before any time base: for the actuator to
  // follow the turntable with the least delay (rig/contact_follower.hpp). On the USB rig it runs
  // on the driver's event thread, elsewhere in read(); it must not block. Set before start(); the
  // listener must outlive the run.
  virtual void set_frame_listener(const FrameListener* listener) { listener_ = listener; }

  // A rig that plays a recording (the replay rig) runs the profile that was recorded; others none.
  virtual const SpeedProfile* own_profile() const { return nullptr; }

 protected:
  // For rigs that make their frames in read(): tells the listener about the newest of a batch.
  void tell_listener(const std::vector<SensorFrame>& frames, std::size_t from) const {
    if (listener_ != nullptr && frames.size() > from) (*listener_)(frames.back());
  }
  const FrameListener* listener_ = nullptr;
};

}  // namespace nibrig::rig
