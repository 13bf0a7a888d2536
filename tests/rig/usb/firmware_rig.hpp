// The rig controller's real firmware behind the host's real driver: a SimulatedBoard runs the ELF
// in real time on its own thread, and its USB port is bridged to a usbfs node in a umockdev
// testbed, so that libusb's transfers reach the simulated chip's endpoints (and the kernel's
// enumeration is done as the kernel does it, with the firmware's own descriptors). The same
// test-facing calls as EmulatedRig where a real device can honour them: what it holds is read from
// the firmware's memory, and the transport's faults (lost, reordered or repeated frames, a request
// never answered, unplugging) are the bridge's, as a bad cable or host controller would make them.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "rig/firmware/rig_device.h"
#include "rig/speed_profile.hpp"
#include "rig/usb/usb_protocol.hpp"
#include "tests/rig/usb/emulated_rig.hpp"
#include "tests/rig/usb/simulated_board.hpp"
#include "tests/rig/usb/usbfs_device.hpp"

namespace nibrig::rig::usb::testing {

// The firmware the build made (rig/firmware), or empty when it was not built.
std::string firmware_elf();

class FirmwareRig {
 public:
  // Writes `config.serial` into the board's EEPROM (as `nibrig rig calibrate --serial` would),
  // boots the firmware, enumerates it, then adds it to the testbed and runs it in real time.
  FirmwareRig(UMockdevTestbed* testbed, EmulatedRigConfig config, TurntablePhysics physics = {});
  ~FirmwareRig();
  FirmwareRig(const FirmwareRig&) = delete;
  FirmwareRig& operator=(const FirmwareRig&) = delete;

  // The cable: the board stays powered (from its supply), so its clock and sequence run on.
  void unplug();
  void replug(int new_address);
  // Transport faults.
  void drop_frames(unsigned count);
  void reorder_next_packet();
  void duplicate_next_packet();
  void hold_stream(bool hold);  // the host controller stops asking: the firmware's buffer overflows
  void ignore_next_control();   // the next control transfer never reaches the device
  // The world: a tap on the arm, into the frame sampled at or after device time `device_us`.
  void tap(std::uint64_t device_us, double extra_N);
  std::uint64_t tapped_at_us() const;
  void set_normal_force(double newtons);
  // What rests on the arm: a weight on the tip, and one pulling along the track (calibration).
  void place_on_arm(double normal_N, double tangential_N);
  std::chrono::steady_clock::time_point power_up() const { return power_up_; }
  std::uint64_t device_us_at(std::chrono::steady_clock::time_point host) const;

  // What the firmware holds, read from its memory.
  DeviceStatus status() const;
  std::vector<ProfilePoint> held_profile() const;
  ForceCalibration calibration() const;
  std::uint32_t frames_sampled() const;
  bool streaming() const;
  unsigned control_requests() const;
  unsigned frames_duplicated() const;
  std::uint32_t first_streamed_sequence() const;  // of the first frame the host received
  std::vector<std::uint8_t> eeprom() const;
  double surface_speed_m_s() const;

 private:
  void run();
  void service_usb();
  void finish_packet();
  struct rig rig_state() const;

  EmulatedRigConfig config_;
  std::unique_ptr<SimulatedBoard> board_;
  std::unique_ptr<UsbfsDevice> usbfs_;
  std::chrono::steady_clock::time_point power_up_;
  std::chrono::steady_clock::time_point paced_from_;
  std::uint64_t paced_from_cycle_ = 0;

  mutable std::mutex mutex_;  // the board, and the bridge's state: the simulation thread's and the test's
  std::condition_variable wake_;
  bool submitted_ = false;
  bool plugged_ = true;
  std::optional<std::uint64_t> control_id_;  // the transfer the board is carrying
  std::vector<std::uint8_t> packet_;         // the bulk packet being received
  std::vector<std::uint8_t> repeat_;         // frames to send again (duplicate_next_packet)
  unsigned drop_ = 0;
  bool reorder_ = false, duplicate_ = false, hold_ = false, ignore_next_ = false;
  unsigned duplicated_ = 0;
  unsigned control_requests_ = 0;
  bool any_streamed_ = false;
  std::uint32_t first_streamed_ = 0;
  std::uint64_t tapped_at_us_ = 0;

  std::atomic<bool> running_{true};
  std::thread thread_;
};

}  // namespace nibrig::rig::usb::testing
