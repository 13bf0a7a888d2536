#include "tests/rig/usb/firmware_rig.hpp"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "rig/firmware/rig_device.h"

namespace nibrig::rig::usb::testing {
namespace {

constexpr std::uint64_t kSliceCycles = 400;  // 25 us of the chip between two looks at the bus

// An EEPROM image as the firmware's board_persist_* keeps it: a key, then `rig_persist`.
std::vector<std::uint8_t> eeprom_with_serial(const std::string& serial) {
  rig_persist persist;
  rig_persist_defaults(&persist);
  std::memset(persist.serial, 0, sizeof persist.serial);
  std::memcpy(persist.serial, serial.data(), std::min(serial.size(), sizeof persist.serial));
  std::vector<std::uint8_t> image(1024, 0xFF);
  image[0] = 0x31;  // PERSIST_KEY 0x4E31, little-endian
  image[1] = 0x4E;
  std::memcpy(image.data() + 2, &persist, sizeof persist);
  return image;
}

}  // namespace

std::string firmware_elf() {
#ifdef NIBRIG_FIRMWARE_ELF
  return NIBRIG_FIRMWARE_ELF;
#else
  return {};
#endif
}

FirmwareRig::FirmwareRig(UMockdevTestbed* testbed, EmulatedRigConfig config, TurntablePhysics physics)
    : config_(std::move(config)) {
  if (firmware_elf().empty()) throw std::runtime_error("the firmware was not built (NIBRIG_BUILD_FIRMWARE)");
  board_ = std::make_unique<SimulatedBoard>(firmware_elf(), eeprom_with_serial(config_.serial), physics);
  const std::vector<std::uint8_t> descriptors = board_->enumerate(config_.address);
  // From here on the chip runs in step with the host's clock (its crystal `clock_ppm` fast).
  paced_from_ = std::chrono::steady_clock::now();
  paced_from_cycle_ = board_->cycle();
  const double device_s = static_cast<double>(board_->device_us()) * 1e-6 / (1.0 + config_.clock_ppm * 1e-6);
  power_up_ = paced_from_ - std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(device_s));
  usbfs_ = std::make_unique<UsbfsDevice>(testbed, descriptors, kVendorId, kProductId, config_.address, 12);
  usbfs_->on_submit([this] {
    std::lock_guard lock(mutex_);
    submitted_ = true;
    wake_.notify_one();
  });
  thread_ = std::thread([this] { run(); });
}

FirmwareRig::~FirmwareRig() {
  running_ = false;
  wake_.notify_one();
  thread_.join();
  usbfs_->on_submit({});
}

std::uint64_t FirmwareRig::device_us_at(std::chrono::steady_clock::time_point host) const {
  const double elapsed_us = std::chrono::duration<double, std::micro>(host - power_up_).count();
  return static_cast<std::uint64_t>(elapsed_us * (1.0 + config_.clock_ppm * 1e-6));
}

void FirmwareRig::run() {
  // The board is hardware to the host: it must keep real time whatever else the machine runs. A
  // loaded machine (the test job compiles and runs suites on both cores) fell 10-100 ms behind, and
  // the time base then measured the lag. Real-time priority where allowed (root, as in CI), below
  // the JACK server's; elsewhere the default.
  sched_param priority{};
  priority.sched_priority = 20;
  pthread_setschedparam(pthread_self(), SCHED_FIFO, &priority);
  const double cycles_per_host_us = 16.0 * (1.0 + config_.clock_ppm * 1e-6);
  while (running_) {
    std::unique_lock lock(mutex_);
    const double host_us =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - paced_from_).count();
    const auto due = paced_from_cycle_ + static_cast<std::uint64_t>(host_us * cycles_per_host_us);
    if (board_->cycle() + kSliceCycles <= due) {
      board_->run_to_cycle(board_->cycle() + kSliceCycles);
    } else {
      // Ahead of the host: wait for its clock, or for a transfer to carry.
      wake_.wait_for(lock, std::chrono::microseconds(50), [this] { return submitted_ || !running_; });
      submitted_ = false;
    }
    service_usb();
  }
}

// One look at the bus, as a host controller's schedule would: the control transfer in progress
// moves a stage, and the stream's endpoint gives a packet if a bulk transfer waits for one.
void FirmwareRig::service_usb() {
  if (!plugged_) return;
  if (!control_id_) {
    if (auto transfer = usbfs_->take_control()) {
      ++control_requests_;
      if (ignore_next_) {
        ignore_next_ = false;  // it never reaches the device: libusb times out and discards it
      } else {
        control_id_ = transfer->id;
        board_->begin_control(transfer->setup, transfer->out, transfer->in_capacity);
      }
    }
  }
  if (control_id_) {
    if (auto outcome = board_->step_control()) {
      usbfs_->complete_control(*control_id_, outcome->status, outcome->in);
      control_id_.reset();
    }
  }
  if (!hold_ && usbfs_->bulk_in_waiting(kStreamEndpoint)) {
    if (auto chunk = board_->bulk_in_packet(kStreamEndpoint)) {
      packet_.insert(packet_.end(), chunk->begin(), chunk->end());
      // A short USB packet ends the transfer (the firmware never sends a multiple of 64 bytes).
      if (chunk->size() < 64) finish_packet();
    }
  }
}

// The packet as the host receives it, after the faults asked for.
void FirmwareRig::finish_packet() {
  std::vector<std::uint8_t> bytes;
  bytes.swap(packet_);
  std::array<SensorFrame, kMaxFramesPerPacket> decoded{};
  const PacketDecode d = decode_frame_packet(bytes, decoded);
  if (d.frames > 0) {
    if (!any_streamed_) first_streamed_ = decoded[0].sequence;
    any_streamed_ = true;
  }
  if (drop_ == 0 && !reorder_ && !duplicate_ && repeat_.empty()) {
    usbfs_->complete_bulk_in(kStreamEndpoint, bytes.data(), bytes.size());
    return;
  }
  std::vector<SensorFrame> frames(decoded.begin(), decoded.begin() + static_cast<std::ptrdiff_t>(d.frames));
  std::vector<SensorFrame> again;
  if (!repeat_.empty()) {
    std::array<SensorFrame, kMaxFramesPerPacket> previous{};
    const PacketDecode p = decode_frame_packet(repeat_, previous);
    again.assign(previous.begin(), previous.begin() + static_cast<std::ptrdiff_t>(p.frames));
    repeat_.clear();
  }
  while (drop_ > 0 && !frames.empty()) {
    frames.erase(frames.begin());
    --drop_;
  }
  if (reorder_ && frames.size() >= 2) {
    std::swap(frames[0], frames[1]);
    reorder_ = false;
  }
  if (duplicate_ && !frames.empty()) {
    repeat_ = encode_frame_packet(frames);
    duplicated_ += static_cast<unsigned>(frames.size());
    duplicate_ = false;
  }
  frames.insert(frames.begin(), again.begin(), again.end());
  if (frames.empty()) return;  // all lost: the transfer waits for the next packet
  const auto packet = encode_frame_packet(frames);
  usbfs_->complete_bulk_in(kStreamEndpoint, packet.data(), packet.size());
}

void FirmwareRig::unplug() {
  {
    std::lock_guard lock(mutex_);
    plugged_ = false;
    packet_.clear();
    control_id_.reset();
  }
  usbfs_->unplug();
}

void FirmwareRig::replug(int new_address) {
  config_.address = new_address;
  {
    // The kernel enumerates it again: a bus reset, then its requests, in the board's time.
    std::lock_guard lock(mutex_);
    board_->enumerate(new_address);
    paced_from_ = std::chrono::steady_clock::now();
    paced_from_cycle_ = board_->cycle();
    plugged_ = true;
  }
  usbfs_->replug(new_address);
}

void FirmwareRig::drop_frames(unsigned count) {
  std::lock_guard lock(mutex_);
  drop_ += count;
}
void FirmwareRig::reorder_next_packet() {
  std::lock_guard lock(mutex_);
  reorder_ = true;
}
void FirmwareRig::duplicate_next_packet() {
  std::lock_guard lock(mutex_);
  duplicate_ = true;
}
void FirmwareRig::hold_stream(bool hold) {
  std::lock_guard lock(mutex_);
  hold_ = hold;
}
void FirmwareRig::ignore_next_control() {
  std::lock_guard lock(mutex_);
  ignore_next_ = true;
}

void FirmwareRig::tap(std::uint64_t device_us, double extra_N) {
  std::lock_guard lock(mutex_);
  // The first frame sampled at or after `device_us`, on the firmware's own frame grid.
  const struct rig r = rig_state();
  const std::uint64_t next = board_->next_frame_device_us();
  const std::uint64_t period = 1'000'000 / r.frame_rate_hz;
  std::uint64_t frame = next;
  if (device_us > next) frame += (device_us - next + period - 1) / period * period;
  board_->pulse_force(frame, extra_N);
  tapped_at_us_ = frame;
}

std::uint64_t FirmwareRig::tapped_at_us() const {
  std::lock_guard lock(mutex_);
  return tapped_at_us_;
}

void FirmwareRig::set_normal_force(double newtons) {
  std::lock_guard lock(mutex_);
  board_->set_normal_force(newtons);
}

void FirmwareRig::place_on_arm(double normal_N, double tangential_N) {
  std::lock_guard lock(mutex_);
  board_->set_normal_force(normal_N);
  board_->set_tangential_pull(tangential_N);
}

// The firmware's protocol state as it lies in the chip's RAM (the struct is packed, as on the AVR).
struct rig FirmwareRig::rig_state() const {
  struct rig r;
  const auto bytes = board_->read_symbol("rig", sizeof r);
  std::memcpy(&r, bytes.data(), sizeof r);
  return r;
}

DeviceStatus FirmwareRig::status() const {
  std::lock_guard lock(mutex_);
  const struct rig r = rig_state();
  DeviceStatus s;
  s.flags = r.sticky_flags;
  if (r.mode == RIG_SPEED || r.mode == RIG_PROFILE) s.flags |= RIG_PROFILE_RUNNING;
  s.mode = static_cast<Mode>(r.mode);
  s.fault = static_cast<Fault>(r.fault);
  s.next_sequence = r.sequence;
  s.speed_target_m_s = r.target_mm_s * 1e-3;
  s.profile_points = r.profile_held;
  s.refused_request = r.refused_request;
  s.refusal = r.refusal;
  return s;
}

std::vector<ProfilePoint> FirmwareRig::held_profile() const {
  std::lock_guard lock(mutex_);
  const struct rig r = rig_state();
  std::vector<ProfilePoint> points;
  for (unsigned i = 0; i < r.profile_held; ++i) {
    points.push_back({r.profile[i].t_ms / 1000.0, r.profile[i].mm_s / 1000.0});
  }
  return points;
}

ForceCalibration FirmwareRig::calibration() const {
  std::lock_guard lock(mutex_);
  const struct rig r = rig_state();
  return {r.persist.counts_per_N[0], r.persist.counts_per_N[1], r.persist.lever};
}

std::uint32_t FirmwareRig::frames_sampled() const { return status().next_sequence; }

bool FirmwareRig::streaming() const {
  std::lock_guard lock(mutex_);
  const struct rig r = rig_state();
  return r.streaming != 0;
}

unsigned FirmwareRig::control_requests() const {
  std::lock_guard lock(mutex_);
  return control_requests_;
}

std::uint32_t FirmwareRig::first_streamed_sequence() const {
  std::lock_guard lock(mutex_);
  return first_streamed_;
}

unsigned FirmwareRig::frames_duplicated() const {
  std::lock_guard lock(mutex_);
  return duplicated_;
}

std::vector<std::uint8_t> FirmwareRig::eeprom() const {
  std::lock_guard lock(mutex_);
  return board_->eeprom();
}

double FirmwareRig::surface_speed_m_s() const {
  std::lock_guard lock(mutex_);
  return board_->surface_speed_m_s();
}

}  // namespace nibrig::rig::usb::testing
