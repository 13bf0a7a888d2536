#include "tests/rig/usb/board_host.hpp"

#include <array>
#include <stdexcept>

#include "tests/rig/usb/firmware_rig.hpp"

namespace nibrig::rig::usb::testing {
namespace {

constexpr double kBoardHostSliceUs = 25.0;  // a look at the bus every 25 us, as FirmwareRig does
constexpr double kBoardHostTransferLimitUs = 5e6;  // a host gives a control transfer 5 s

std::array<std::uint8_t, 8> board_host_setup(bool in, Request request, std::uint16_t value, std::uint16_t index,
                                             std::uint16_t length) {
  return {in ? kRequestTypeIn : kRequestTypeOut, static_cast<std::uint8_t>(request),
          static_cast<std::uint8_t>(value), static_cast<std::uint8_t>(value >> 8),
          static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8),
          static_cast<std::uint8_t>(length), static_cast<std::uint8_t>(length >> 8)};
}

std::string board_host_firmware() {
  const std::string elf = firmware_elf();
  if (elf.empty()) throw std::runtime_error("the firmware was not built (NIBRIG_BUILD_FIRMWARE)");
  return elf;
}

}  // namespace

BoardHost::BoardHost(const std::vector<std::uint8_t>& eeprom, TurntablePhysics physics)
    : board_(board_host_firmware(), eeprom, physics) {
  board_.enumerate(5);
  last_request_us_ = board_.sim_us();
  next_true_speed_us_ = board_.sim_us();
}

void BoardHost::enumerate_again() {
  keepalive_in_flight_ = false;
  packet_.clear();
  board_.enumerate(5);
  last_request_us_ = board_.sim_us();
}

void BoardHost::slice() {
  board_.run_us(kBoardHostSliceUs);
  // A bulk transfer always waits: every USB packet the firmware offers is taken at once.
  while (auto chunk = board_.bulk_in_packet(kStreamEndpoint)) {
    packet_.insert(packet_.end(), chunk->begin(), chunk->end());
    if (chunk->size() < 64) {
      finish_packet();
      break;
    }
  }
  if (board_.sim_us() >= next_true_speed_us_) {
    true_speeds_.push_back(
        {board_.sim_us(), board_.surface_speed_m_s() * 1e3, board_.duty(), board_.sensed_current_A()});
    next_true_speed_us_ += 1000.0;
  }
}

void BoardHost::finish_packet() {
  std::array<SensorFrame, kMaxFramesPerPacket> decoded{};
  const PacketDecode d = decode_frame_packet(packet_, decoded);
  if (d.error != nullptr) throw std::runtime_error(std::string("the firmware sent a bad frame packet: ") + d.error);
  for (std::size_t i = 0; i < d.frames; ++i) frames_.push_back({decoded[i], board_.sim_us()});
  packet_.clear();
}

void BoardHost::run_us(double us) {
  const double end = board_.sim_us() + us;
  while (board_.sim_us() < end) {
    slice();
    if (keepalive_in_flight_) {
      if (board_.step_control()) keepalive_in_flight_ = false;
    } else if (keepalive_us_ > 0.0 && board_.sim_us() - last_request_us_ >= keepalive_us_) {
      board_.begin_control(board_host_setup(true, Request::kGetStatus, 0, 0, kStatusBytes12), {}, kStatusBytes12);
      keepalive_in_flight_ = true;
      last_request_us_ = board_.sim_us();
    }
  }
}

ControlOutcome BoardHost::out(Request request, std::uint16_t value, std::uint16_t index,
                              const std::vector<std::uint8_t>& data) {
  return carry(board_host_setup(false, request, value, index, static_cast<std::uint16_t>(data.size())), data, 0);
}

ControlOutcome BoardHost::in(Request request, std::uint16_t length, std::uint16_t value, std::uint16_t index) {
  return carry(board_host_setup(true, request, value, index, length), {}, length);
}

// One control transfer, stage by stage, with the bus looked at between stages as a controller would.
ControlOutcome BoardHost::carry(const std::array<std::uint8_t, 8>& setup, const std::vector<std::uint8_t>& data,
                                std::size_t in_capacity) {
  while (keepalive_in_flight_) run_us(kBoardHostSliceUs);
  board_.begin_control(setup, data, in_capacity);
  last_request_us_ = board_.sim_us();
  const double deadline = board_.sim_us() + kBoardHostTransferLimitUs;
  while (board_.sim_us() < deadline) {
    slice();
    if (auto outcome = board_.step_control()) return *outcome;
  }
  throw std::runtime_error("the simulated firmware did not complete " + request_name(setup[1]));
}

void BoardHost::require_out(Request request, std::uint16_t value, std::uint16_t index,
                            const std::vector<std::uint8_t>& data) {
  if (out(request, value, index, data).status != 0) {
    throw std::runtime_error("the simulated firmware refused " + request_name(static_cast<std::uint8_t>(request)));
  }
}

std::vector<std::uint8_t> BoardHost::require_in(Request request, std::uint16_t length, std::uint16_t value,
                                                std::uint16_t index) {
  ControlOutcome o = in(request, length, value, index);
  if (o.status != 0) {
    throw std::runtime_error("the simulated firmware refused " + request_name(static_cast<std::uint8_t>(request)));
  }
  return o.in;
}

DeviceStatus BoardHost::status() { return decode_status(require_in(Request::kGetStatus, kStatusBytes12)); }

void BoardHost::set_speed_mm_s(float mm_s) {
  const auto bytes = encode_speed(mm_s * 1e-3);
  require_out(Request::kSetSpeed, 0, 0, {bytes.begin(), bytes.end()});
}

double BoardHost::sim_us_at_device_us(std::uint64_t device_us) const {
  return static_cast<double>(board_.clock_start_cycle() + device_us * 16) / 16.0;
}

void BoardHost::clear_records() {
  frames_.clear();
  true_speeds_.clear();
}

}  // namespace nibrig::rig::usb::testing
