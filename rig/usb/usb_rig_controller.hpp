// The driver of the USB rig controller (PROTOCOL.md): control requests from the caller's thread, and
// an event thread of its own that keeps a pool of bulk IN transfers in flight, decodes the frames
// into a lock-free queue, keeps the device's watchdog fed, and notices an unplug (hotplug or a
// transfer's NO_DEVICE) and the return of the same serial, which it reopens and streams again.
// A consumer (the capture, the live stroke) drains frames without a libusb call or a lock.
#pragma once

#include <libusb.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "rig/sensor_frame.hpp"
#include "rig/speed_profile.hpp"
#include "rig/usb/sequence_tracker.hpp"
#include "rig/usb/usb_control.hpp"
#include "rig/usb/usb_device_list.hpp"
#include "rig/usb/usb_protocol.hpp"
#include "rig/usb/usb_rig_error.hpp"
#include "rt/spsc_queue.hpp"

namespace nibrig::rig::usb {

// What the driver has seen, readable from any thread (a copy under a short lock; not for an audio
// thread, which reads frames only).
struct UsbRigStatus {
  bool connected = false;
  std::string serial;
  std::uint64_t frames_received = 0;  // delivered into the queue
  std::uint64_t frames_dropped = 0;   // sequence numbers never seen
  std::uint64_t frames_reordered = 0; // arrived after a later one: counted, not delivered
  std::uint64_t frames_duplicated = 0;
  std::uint64_t queue_overflows = 0;  // decoded but the consumer's queue was full
  std::uint64_t malformed_packets = 0;
  std::uint64_t transfer_timeouts = 0;  // bulk transfers that ended without data in time
  std::uint64_t disconnects = 0;
  std::uint64_t reconnects = 0;
  std::uint16_t device_flags = 0;  // SensorFlag bits of the newest frame or status
  std::string last_fault;          // one line; empty while nothing went wrong
  // The fault the device stopped the motor for since the last start, with what to check; empty
  // while the motor may run.
  std::string device_fault;
};

class UsbRigController {
 public:
  struct Options {
    std::string serial;  // empty: the only controller on the bus
    unsigned transfers_in_flight = 8;
    std::chrono::milliseconds transfer_timeout{100};
    // GET_STATUS every so often keeps the watchdog from stopping the motor (PROTOCOL.md
    // "Watchdog"); 0 uses a third of the device's timeout. `keep_alive = false` lets the motor stop
    // whenever the host's own calls stop: the watchdog test, or a host that wants exactly that.
    std::chrono::milliseconds keep_alive_period{0};
    bool keep_alive = true;
    std::chrono::milliseconds rescan_period{200};  // looking for the serial again while unplugged
    std::size_t queue_frames = 1 << 16;            // 65 s at 1 kHz for a consumer that falls behind
    unsigned control_timeout_ms = 1000;
  };

  // Opens the controller, identifies it and starts streaming. Throws UsbRigError when it is missing
  // (naming what was found), ambiguous, or speaks another major protocol version.
  explicit UsbRigController(Options options);
  UsbRigController() : UsbRigController(Options{}) {}
  // Stops the motor and the stream (a host that leaves should not leave the turntable running
  // until the watchdog notices), then closes the device.
  ~UsbRigController();
  UsbRigController(const UsbRigController&) = delete;
  UsbRigController& operator=(const UsbRigController&) = delete;

  // The identity read at the last (re)connect.
  Identity identity() const;
  // Control requests; each throws UsbRigError naming the device and request (unplugged, refused
  // with the device's reason, no answer).
  Identity identify();
  void set_speed(double speed_m_s);
  // Refuses a profile beyond the motor's speed or the device's point count, stating the range.
  void upload_profile(const SpeedProfile& profile);
  std::vector<ProfilePoint> read_profile();
  void start_profile();
  void stop();
  void zero_force();
  void set_frame_rate(unsigned frames_per_second);
  DeviceStatus device_status();
  ForceCalibration calibration();
  void set_calibration(const ForceCalibration& calibration);
  // Version 1.1's requests (PROTOCOL.md "Version 1.1"). A 1.0 device is not asked: the error names
  // its version and the one the request needs.
  Geometry geometry();
  // Refuses a value that is not finite or not above 0 before the device does, naming it.
  void set_geometry(const Geometry& geometry);
  // The device keeps the new serial; identity() reports it from here on, but the driver still
  // reconnects to the serial it opened (a replug after a rename needs a new controller).
  void set_serial(const std::string& serial);
  // The device leaves the bus for its bootloader: this controller sees it unplugged. Refused by the
  // device while the motor runs.
  void enter_bootloader();

  // Consumer side (one thread): the frames decoded so far, oldest first, up to out.size(). No
  // libusb call, no lock, no allocation.
  std::size_t read_frames(std::span<SensorFrame> out) noexcept;

  UsbRigStatus status() const;

  // Called on the event thread with each frame delivered, right after it is queued (the actuator
  // following the turntable). It must not block. nullptr: none. The listener must outlive the
  // controller or be removed first.
  void set_frame_listener(const std::function<void(const SensorFrame&)>* listener) noexcept {
    listener_.store(listener, std::memory_order_release);
  }

 private:
  struct Transfer;
  // Runs `f` with the open device's control channel, under the device lock so that the event
  // thread cannot close the handle meanwhile.
  template <typename F>
  auto with_channel(F&& f) {
    std::lock_guard lock(device_mutex_);
    if (handle_ == nullptr || lost_) {
      throw UsbRigError("the rig controller " + serial_ +
                        " is unplugged; the driver reconnects when it comes back");
    }
    ControlChannel channel(handle_, "the rig controller " + serial_, options_.control_timeout_ms);
    return f(channel);
  }
  // Throws unless the device speaks at least `version` (the request's).
  void require_version(Request request, std::uint16_t version) const;
  void event_loop();
  void start_streaming();  // event thread or constructor: claim, SET_STREAMING(1), submit the pool
  void close_device();     // event thread: after every transfer is back
  void try_reconnect();
  void submit_keep_alive();
  void set_fault(std::string fault);
  void clear_device_fault();
  static void LIBUSB_CALL on_bulk(libusb_transfer* transfer);
  static void LIBUSB_CALL on_keep_alive(libusb_transfer* transfer);
  static int LIBUSB_CALL on_hotplug(libusb_context*, libusb_device*, libusb_hotplug_event, void*);
  void handle_packet(const libusb_transfer* transfer);

  Options options_;
  libusb_context* context_ = nullptr;
  libusb_hotplug_callback_handle hotplug_ = 0;
  bool has_hotplug_ = false;

  // The open device: opened and closed by the event thread (or the constructor before it runs),
  // used by control threads under the mutex.
  mutable std::mutex device_mutex_;
  libusb_device_handle* handle_ = nullptr;
  Identity identity_;
  std::string serial_;  // the one to come back: asked for, or the first one opened

  std::vector<std::unique_ptr<Transfer>> transfers_;
  libusb_transfer* keep_alive_ = nullptr;
  std::vector<std::uint8_t> keep_alive_buffer_;
  std::atomic<bool> keep_alive_in_flight_{false};  // its callback may run on a control thread
  std::atomic<int> in_flight_{0};  // bulk transfers out; callbacks may run on a control thread
  SequenceTracker tracker_;            // touched in callbacks only

  std::atomic<bool> stopping_{false};
  std::atomic<bool> lost_{false};          // unplug seen, device not yet closed
  std::atomic<bool> arrival_seen_{false};  // hotplug said a controller arrived

  rt::SpscQueue<SensorFrame> queue_;
  std::atomic<const std::function<void(const SensorFrame&)>*> listener_{nullptr};

  // The snapshot's counters: written by callbacks, read by status().
  std::atomic<bool> connected_{false};
  std::atomic<std::uint64_t> received_{0}, dropped_{0}, reordered_{0}, duplicated_{0},
      overflows_{0}, malformed_{0}, timeouts_{0}, disconnects_{0}, reconnects_{0};
  std::atomic<std::uint16_t> device_flags_{0};
  mutable std::mutex fault_mutex_;
  std::string last_fault_;
  std::string device_fault_;

  std::thread events_;
};

}  // namespace nibrig::rig::usb
