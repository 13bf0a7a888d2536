#include "tests/rig/usb/emulated_rig.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace nibrig::rig::usb::testing {
namespace {

constexpr double kMotorTau_s = 0.05;  // the speed loop's first-order response
constexpr std::uint64_t kPacketAgeUs = 8000;  // PROTOCOL.md: a packet at least every 10 ms

// Device, configuration, interface and one bulk IN endpoint descriptor (PROTOCOL.md "Device").
std::vector<std::uint8_t> descriptors() {
  return {18, 1, 0x00, 0x02, 0xFF, 0, 0, 64,              // USB 2.0, vendor class, EP0 64 bytes
          kVendorId & 0xFF, kVendorId >> 8, kProductId & 0xFF, kProductId >> 8,
          0x00, 0x01, 0, 0, 0, 1,                         // bcdDevice 1.00, no strings, 1 config
          9, 2, 25, 0, 1, 1, 0, 0x80, 50,                 // config 1: 25 bytes, 1 interface
          9, 4, 0, 0, 1, 0xFF, 0, 0, 0,                   // interface 0: 1 endpoint, vendor class
          7, 5, kStreamEndpoint, 2, 0x00, 0x02, 0};       // bulk IN 0x81, 512 bytes
}

}  // namespace

EmulatedRig::EmulatedRig(UMockdevTestbed* testbed, EmulatedRigConfig config)
    : config_(std::move(config)),
      power_up_(std::chrono::steady_clock::now() - std::chrono::seconds(5)),  // on for a while
      usbfs_(testbed, descriptors(), kVendorId, kProductId, config_.address, 480),
      frame_rate_hz_(config_.frame_rate_hz) {
  next_sample_us_ = clock_us();
  last_control_us_ = clock_us();
  usbfs_.on_submit([this] {
    std::lock_guard lock(mutex_);
    submitted_ = true;
    wake_.notify_one();
  });
  firmware_ = std::thread([this] { firmware_loop(); });
}

EmulatedRig::~EmulatedRig() {
  running_ = false;
  wake_.notify_one();
  firmware_.join();
  usbfs_.on_submit({});
}

void EmulatedRig::unplug() {
  {
    std::lock_guard lock(mutex_);
    plugged_ = false;
    streaming_ = false;  // a device without power streams nothing
  }
  usbfs_.unplug();
}

void EmulatedRig::replug(int new_address) {
  config_.address = new_address;
  {
    std::lock_guard lock(mutex_);
    mode_ = Mode::kIdle;  // it lost power: the motor is at rest
    target_m_s_ = 0.0;
    plugged_ = true;
  }
  usbfs_.replug(new_address);
}

void EmulatedRig::drop_frames(unsigned count) {
  std::lock_guard lock(mutex_);
  drop_ += count;
}
void EmulatedRig::reorder_next_packet() {
  std::lock_guard lock(mutex_);
  reorder_ = true;
}
void EmulatedRig::duplicate_next_packet() {
  std::lock_guard lock(mutex_);
  duplicate_ = true;
}
bool EmulatedRig::streaming() const {
  std::lock_guard lock(mutex_);
  return streaming_;
}
unsigned EmulatedRig::frames_duplicated() const {
  std::lock_guard lock(mutex_);
  return duplicated_;
}
void EmulatedRig::tap(std::uint64_t device_us, double extra_N) {
  std::lock_guard lock(mutex_);
  tap_ = std::make_pair(device_us, extra_N);
}

std::uint64_t EmulatedRig::tapped_at_us() const {
  std::lock_guard lock(mutex_);
  return tapped_at_us_;
}

void EmulatedRig::hold_stream(bool hold) {
  std::lock_guard lock(mutex_);
  hold_ = hold;
}
void EmulatedRig::refuse_next(Request request, Refusal why) {
  std::lock_guard lock(mutex_);
  refuse_next_ = std::make_pair(static_cast<std::uint8_t>(request), why);
}
void EmulatedRig::ignore_next_control() {
  std::lock_guard lock(mutex_);
  ignore_next_ = true;
}

DeviceStatus EmulatedRig::status() const {
  std::lock_guard lock(mutex_);
  return {flags_, mode_, fault_, sequence_, target_m_s_,
          static_cast<std::uint16_t>(profile_ ? profile_->points().size() : 0), refused_request_, refusal_};
}
std::vector<ProfilePoint> EmulatedRig::held_profile() const {
  std::lock_guard lock(mutex_);
  return profile_ ? profile_->points() : std::vector<ProfilePoint>{};
}
ForceCalibration EmulatedRig::calibration() const {
  std::lock_guard lock(mutex_);
  return calibration_;
}
std::uint32_t EmulatedRig::frames_sampled() const {
  std::lock_guard lock(mutex_);
  return sequence_;
}
std::uint32_t EmulatedRig::first_streamed_sequence() const {
  std::lock_guard lock(mutex_);
  return first_streamed_;
}
std::uint32_t EmulatedRig::last_sent_sequence() const {
  std::lock_guard lock(mutex_);
  return last_sent_;
}
unsigned EmulatedRig::control_requests() const {
  std::lock_guard lock(mutex_);
  return control_requests_;
}

std::uint64_t EmulatedRig::clock_us() const { return device_us_at(std::chrono::steady_clock::now()); }

std::uint64_t EmulatedRig::device_us_at(std::chrono::steady_clock::time_point host) const {
  const double elapsed_us = std::chrono::duration<double, std::micro>(host - power_up_).count();
  return static_cast<std::uint64_t>(elapsed_us * (1.0 + config_.clock_ppm * 1e-6));
}

// Every control transfer waiting, answered as the device's firmware would (or never, on demand).
void EmulatedRig::answer_control() {
  while (auto transfer = usbfs_.take_control()) {
    Reply reply;
    {
      std::lock_guard lock(mutex_);
      ++control_requests_;
      last_control_us_ = clock_us();
      reply = control(transfer->setup.data(), transfer->out.data());
    }
    if (reply.ignore) continue;  // never answered: libusb times out and discards it
    usbfs_.complete_control(transfer->id, reply.stall ? -EPIPE : 0, reply.data);
  }
}

void EmulatedRig::firmware_loop() {
  while (running_) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait_for(lock, std::chrono::microseconds(500), [this] { return submitted_ || !running_; });
      submitted_ = false;
    }
    answer_control();
    std::lock_guard lock(mutex_);
    const std::uint64_t now = clock_us();
    // Watchdog (PROTOCOL.md): the motor stops when the host has been silent too long.
    if ((mode_ == Mode::kSpeed || mode_ == Mode::kProfile) && now - last_control_us_ > 500'000) {
      mode_ = Mode::kIdle;
      target_m_s_ = 0.0;
      fault_ = Fault::kWatchdog;
      flags_ |= kWatchdogStopped;
    }
    if (mode_ == Mode::kProfile && profile_) {
      const double t = static_cast<double>(now - profile_start_us_) * 1e-6;
      target_m_s_ = profile_->speed_at(t);
      if (t > profile_->duration_s()) mode_ = Mode::kProfileDone;
    }
    if (mode_ == Mode::kSpeed || mode_ == Mode::kProfile) {
      flags_ |= kProfileRunning;
    } else {
      flags_ &= static_cast<std::uint16_t>(~kProfileRunning);
    }
    sample_until(now);
    if (plugged_) send_packets(now);
  }
}

void EmulatedRig::sample_until(std::uint64_t now_us) {
  const std::uint64_t period_us = 1'000'000 / frame_rate_hz_;
  while (next_sample_us_ <= now_us) {
    const double dt = static_cast<double>(period_us) * 1e-6;
    speed_m_s_ += (target_m_s_ - speed_m_s_) * (1.0 - std::exp(-dt / kMotorTau_s));
    SensorFrame f;
    f.device_time_us = next_sample_us_;
    f.sequence = sequence_++;
    f.speed_m_s = static_cast<float>(speed_m_s_);
    f.normal_force_N = static_cast<float>(kLoadN - force_zero_N_);
    f.tangential_force_N = static_cast<float>(0.3 * (kLoadN - force_zero_N_));
    f.flags = flags_;
    if (tap_ && next_sample_us_ >= tap_->first) {
      f.normal_force_N += static_cast<float>(tap_->second);
      tapped_at_us_ = next_sample_us_;
      tap_.reset();
    }
    next_sample_us_ += period_us;
    if (!streaming_ || !plugged_) continue;
    if (drop_ > 0) {  // sampled, never sent: a gap in the sequence
      --drop_;
      continue;
    }
    if (!any_streamed_) {
      any_streamed_ = true;
      first_streamed_ = f.sequence;
    }
    fifo_.push_back(f);
    if (fifo_.size() > 8192) fifo_.pop_front();  // the device's buffer: the oldest is lost
  }
}

void EmulatedRig::send_packets(std::uint64_t now_us) {
  while (!hold_ && usbfs_.bulk_in_waiting(kStreamEndpoint) && !fifo_.empty() &&
         (fifo_.size() >= config_.frames_per_packet || now_us - fifo_.front().device_time_us >= kPacketAgeUs)) {
    const std::size_t n = std::min<std::size_t>({fifo_.size(), config_.frames_per_packet, kMaxFramesPerPacket});
    std::vector<SensorFrame> frames(fifo_.begin(), fifo_.begin() + static_cast<std::ptrdiff_t>(n));
    fifo_.erase(fifo_.begin(), fifo_.begin() + static_cast<std::ptrdiff_t>(n));
    if (duplicate_) {  // the same frames again at the head of the queue: the next packet repeats them
      fifo_.insert(fifo_.begin(), frames.begin(), frames.end());
      duplicated_ += static_cast<unsigned>(frames.size());
      duplicate_ = false;
    }
    if (reorder_ && frames.size() >= 2) {
      std::swap(frames[0], frames[1]);
      reorder_ = false;
    }
    for (const auto& f : frames) last_sent_ = std::max(last_sent_, f.sequence);
    const auto packet = encode_frame_packet(frames);
    usbfs_.complete_bulk_in(kStreamEndpoint, packet.data(), packet.size());
  }
}

}  // namespace nibrig::rig::usb::testing
