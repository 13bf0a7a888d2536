// A rig controller that exists only in the test process: umockdev shows libusb a USB device
// (1209:000a, usbfs_device.hpp) whose transfers this object answers as a device built from
// rig/PROTOCOL.md would — control requests, a bulk stream sampled on its own microsecond clock,
// the watchdog — and misbehaves on demand (STALL, silence, lost and reordered frames, unplug and
// replug). Run the test binary under umockdev-wrapper.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "rig/sensor_frame.hpp"
#include "rig/speed_profile.hpp"
#include "rig/usb/usb_protocol.hpp"
#include "tests/rig/usb/usbfs_device.hpp"

namespace nibrig::rig::usb::testing {

struct EmulatedRigConfig {
  std::string serial = "NIB-0001";
  int address = 2;  // on bus 1
  double max_speed_m_s = 0.3;
  std::uint16_t max_profile_points = 64;
  unsigned frame_rate_hz = 1000;
  unsigned frames_per_packet = 8;
  std::uint16_t protocol_version = kProtocolVersion;
  // The device's crystal against the host's: its microsecond clock runs this many ppm fast.
  double clock_ppm = 0.0;
};

class EmulatedRig {
 public:
  // Adds the device to the testbed (which must outlive this object) and starts its firmware.
  EmulatedRig(UMockdevTestbed* testbed, EmulatedRigConfig config);
  ~EmulatedRig();
  EmulatedRig(const EmulatedRig&) = delete;
  EmulatedRig& operator=(const EmulatedRig&) = delete;

  // Faults on demand.
  void unplug();                       // pending transfers fail, the node and sysfs entry go away
  void replug(int new_address);        // the same device (serial, clock, sequence) at a new address
  void drop_frames(unsigned count);    // the next `count` frames sampled are never sent
  void reorder_next_packet();          // the next packet's first two frames are swapped
  void duplicate_next_packet();        // the next packet's frames are sent again in the one after
  void hold_stream(bool hold);         // no packet is sent while held: bulk transfers time out
  void refuse_next(Request request, Refusal why);  // the next such request STALLs
  void ignore_next_control();          // the next control request is never answered
  // A tap on the arm: the first frame sampled at or after device time `device_us` reads
  // `extra_N` more normal force (a sharp event the time-base tests find in both streams).
  void tap(std::uint64_t device_us, double extra_N);
  // The device time of the frame the last tap went into (0 until then).
  std::uint64_t tapped_at_us() const;
  // The host's steady clock at device time 0, and the device time at a host instant: the truth the
  // time-base tests compare with (device = (host - power_up) · (1 + ppm)).
  std::chrono::steady_clock::time_point power_up() const { return power_up_; }
  std::uint64_t device_us_at(std::chrono::steady_clock::time_point host) const;

  // What the device saw and holds.
  DeviceStatus status() const;
  std::vector<ProfilePoint> held_profile() const;  // as the device stores it (ms, f32 mm/s)
  ForceCalibration calibration() const;
  std::uint32_t frames_sampled() const;  // the next sequence number
  std::uint32_t first_streamed_sequence() const;
  std::uint32_t last_sent_sequence() const;
  unsigned control_requests() const;
  unsigned frames_duplicated() const;  // sent a second time on request
  bool streaming() const;               // SET_STREAMING's state

  // Version 1.1 and calibration (emulated_rig_requests.cpp). What lies on the arm, at the tip:
  // from the first call on, the frames' forces come from the sensor model of the block below
  // through the device's calibration, so that a calibration changes what the frames read.
  void place_on_arm(double normal_N, double tangential_N);
  Geometry geometry() const;
  bool entered_bootloader() const;  // ENTER_BOOTLOADER was accepted

 private:
  static constexpr double kLoadN = 2.2;  // the arm's load: the paper's normal force
  static constexpr double kForceFullScaleN = 20.0;

  struct Reply {
    bool stall = false;
    bool ignore = false;
    std::vector<std::uint8_t> data;
  };

  Reply control(const std::uint8_t* setup, const std::uint8_t* data);
  Reply refuse(std::uint8_t request, Refusal why);
  void answer_control();
  void firmware_loop();
  void sample_until(std::uint64_t now_us);
  void send_packets(std::uint64_t now_us);
  std::uint64_t clock_us() const;

  EmulatedRigConfig config_;
  std::chrono::steady_clock::time_point power_up_;
  UsbfsDevice usbfs_;

  mutable std::mutex mutex_;  // the firmware thread's and the test's own
  std::condition_variable wake_;
  bool submitted_ = false;
  bool plugged_ = true;
  // Device state (PROTOCOL.md).
  bool streaming_ = false;
  Mode mode_ = Mode::kIdle;
  Fault fault_ = Fault::kNone;
  std::uint16_t flags_ = 0;
  double target_m_s_ = 0.0;
  double speed_m_s_ = 0.0;
  unsigned frame_rate_hz_;
  std::uint64_t next_sample_us_ = 0;
  std::uint64_t last_control_us_ = 0;
  std::uint64_t profile_start_us_ = 0;
  std::uint32_t sequence_ = 0;
  std::uint32_t first_streamed_ = 0;
  bool any_streamed_ = false;
  std::uint32_t last_sent_ = 0;
  std::deque<SensorFrame> fifo_;
  std::uint16_t upload_expected_ = 0;
  std::vector<ProfilePoint> upload_;
  std::optional<SpeedProfile> profile_;
  ForceCalibration calibration_{1000.0, 1000.0, 1.0};
  double force_zero_N_ = 0.0;
  std::uint8_t refused_request_ = 0;
  std::uint8_t refusal_ = 0;
  unsigned control_requests_ = 0;
  // Faults.
  unsigned drop_ = 0;
  bool reorder_ = false;
  bool duplicate_ = false;
  unsigned duplicated_ = 0;
  bool hold_ = false;
  std::optional<std::pair<std::uint64_t, double>> tap_;  // device time, extra newtons
  std::uint64_t tapped_at_us_ = 0;
  std::optional<std::pair<std::uint8_t, Refusal>> refuse_next_;
  bool ignore_next_ = false;

  // Version 1.1 and the force sensors behind the calibration (emulated_rig_requests.cpp). The
  // bridges' true counts per newton and offsets differ from the calibration the device starts
  // with, so that only a calibration makes the frames read the load. The frames' forces are
  // kLoadN − force_zero_N_ (normal) and 0.3 times that (tangential): the model sets force_zero_N_
  // so that the loaded channel reads what the device reports; with a load on the tangential
  // channel alone, the normal frames carry the tangential reading / 0.3 and mean nothing.
  struct ArmLoad {
    double normal_N = 0.0;
    double tangential_N = 0.0;
  };
  std::optional<ArmLoad> arm_load_;
  static constexpr double kTrueNormalCountsPerN = 1150.0;
  static constexpr double kTrueTangentialCountsPerN = 880.0;
  static constexpr double kNormalOffsetCounts = 310.0;
  static constexpr double kTangentialOffsetCounts = -125.0;
  double normal_zero_counts_ = 0.0;
  double tangential_zero_counts_ = 0.0;
  Geometry geometry_{4480.0, 0.060};
  bool entered_bootloader_ = false;
  void apply_arm_model();  // under mutex_
  Reply control_1_1(std::uint8_t request, unsigned value, bool in, unsigned length,
                    std::span<const std::uint8_t> payload);

  std::atomic<bool> running_{true};
  std::thread firmware_;
};

}  // namespace nibrig::rig::usb::testing
