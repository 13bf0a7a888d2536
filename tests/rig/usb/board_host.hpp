// A host on the simulated board's USB port, in simulated time: it enumerates the firmware, keeps a
// bulk transfer always waiting on the stream's endpoint, and carries control requests stage by
// stage between slices of the chip's time, so that a test measures the firmware itself (its speed
// loop, stream and faults) with no real time and no usbfs in between.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rig/sensor_frame.hpp"
#include "rig/usb/usb_protocol.hpp"
#include "tests/rig/usb/simulated_board.hpp"

namespace nibrig::rig::usb::testing {

// A frame as the host received it: the simulated instant its packet's last USB packet was read.
struct ReceivedFrame {
  SensorFrame frame;
  double received_us = 0.0;
};

// The turntable's true state, once a millisecond of simulated time.
struct TrueSpeed {
  double sim_us = 0.0;
  double surface_mm_s = 0.0;
  double duty = 0.0;
  double sensed_A = 0.0;  // what the driver's current mirror carries
};

class BoardHost {
 public:
  // The firmware the build made, powered up with `eeprom` (empty: erased), then enumerated.
  explicit BoardHost(const std::vector<std::uint8_t>& eeprom = {}, TurntablePhysics physics = {});

  SimulatedBoard& board() { return board_; }
  // A new host on the bus (after a reset of the chip, or the old host gone): reset, enumerate.
  void enumerate_again();

  // One vendor request, carried while the chip runs and the stream is read.
  ControlOutcome out(Request request, std::uint16_t value = 0, std::uint16_t index = 0,
                     const std::vector<std::uint8_t>& data = {});
  ControlOutcome in(Request request, std::uint16_t length, std::uint16_t value = 0, std::uint16_t index = 0);
  // The same, throwing when the firmware refuses.
  void require_out(Request request, std::uint16_t value = 0, std::uint16_t index = 0,
                   const std::vector<std::uint8_t>& data = {});
  std::vector<std::uint8_t> require_in(Request request, std::uint16_t length, std::uint16_t value = 0,
                                       std::uint16_t index = 0);
  DeviceStatus status();
  void set_speed_mm_s(float mm_s);

  // Runs the chip for `us` of simulated time, the bus looked at every 25 us as a host controller's
  // schedule would, and GET_STATUS sent every `keepalive_ms` (0: never) as the host driver does.
  void run_us(double us);
  void set_keepalive_ms(double ms) { keepalive_us_ = ms * 1000.0; }

  double sim_us() const { return board_.sim_us(); }
  // The simulated instant at which the device clock read `device_us`.
  double sim_us_at_device_us(std::uint64_t device_us) const;

  const std::vector<ReceivedFrame>& frames() const { return frames_; }
  const std::vector<TrueSpeed>& true_speeds() const { return true_speeds_; }
  void clear_records();

 private:
  ControlOutcome carry(const std::array<std::uint8_t, 8>& setup, const std::vector<std::uint8_t>& data,
                       std::size_t in_capacity);
  void slice();
  void finish_packet();

  SimulatedBoard board_;
  std::vector<std::uint8_t> packet_;
  std::vector<ReceivedFrame> frames_;
  std::vector<TrueSpeed> true_speeds_;
  double next_true_speed_us_ = 0.0;
  double keepalive_us_ = 100'000.0;
  double last_request_us_ = 0.0;
  bool keepalive_in_flight_ = false;
};

}  // namespace nibrig::rig::usb::testing
