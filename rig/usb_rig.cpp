#include "rig/usb_rig.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace nibrig::rig {

UsbRig::UsbRig(const UsbRigSettings& settings)
    : settings_(settings), usb_clock_(0.1, 20), frame_buffer_(1024) {
  controller_ = std::make_unique<usb::UsbRigController>(settings.controller);
  input_ = std::make_unique<AccelerometerInput>(settings.accelerometer);
  const usb::Identity id = controller_->identity();
  const usb::ForceCalibration calibration = controller_->calibration();
  RigDescription& d = description_;
  d.kind = "usb";
  d.name = "USB rig controller " + id.serial + " (firmware " + id.firmware + "), accelerometer on " +
           input_->device_name();
  d.frame_rate_hz = id.frame_rate_hz;
  d.acceleration_rate_hz = input_->sample_rate();
  d.max_speed_m_s = id.max_speed_m_s;
  d.normal_load_N = settings.normal_load_N;
  d.accelerometer_m_s2_per_unit = input_->m_s2_per_full_scale();
  d.force_counts_per_N = calibration.normal_counts_per_N;
  d.lever_factor = calibration.lever_factor;
  d.acceleration_units = "audio full scale";
  samples_per_frame_ = d.acceleration_rate_hz / d.frame_rate_hz;
}

UsbRig::~UsbRig() { controller_->set_frame_listener(nullptr); }

void UsbRig::start(const SpeedProfile& profile) {
  if (started_) throw std::logic_error("USB rig: already started");
  controller_->upload_profile(profile);  // refused beyond the motor, with its range
  // What was captured before the start is not part of the session; the clocks keep their stamps.
  std::vector<float> before;
  input_->read(before);
  drain_frames();
  received_.clear();
  base_index_ = input_->samples_read();
  controller_->start_profile();
  started_ = true;
  frames_total_ = static_cast<std::uint64_t>(std::llround(profile.duration_s() * description_.frame_rate_hz));
}

void UsbRig::drain_frames() {
  for (;;) {
    const std::size_t n = controller_->read_frames(frame_buffer_);
    for (std::size_t i = 0; i < n; ++i) {
      const SensorFrame& f = frame_buffer_[i];
      usb_clock_.add(static_cast<double>(f.device_time_us) * 1e-6, static_cast<double>(f.host_ns) * 1e-9);
      received_.push_back(f);
    }
    if (n < frame_buffer_.size()) break;
  }
}

void UsbRig::drain_acceleration() {
  const std::size_t before = acceleration_.size();
  const std::uint64_t first = acceleration_first_ + before;
  if (input_->read(acceleration_) == 0) return;
  // The block's host time, read now while the callbacks' stamps for it are at hand.
  blocks_.push_back({first, input_->host_time_of(static_cast<double>(first + base_index_))});
  if (blocks_.size() > 4096) blocks_.pop_front();
}

double UsbRig::host_time_of_sample(double n) const {
  for (auto it = blocks_.rbegin(); it != blocks_.rend(); ++it)
    if (static_cast<double>(it->first) <= n)
      return it->host_s + (n - static_cast<double>(it->first)) / description_.acceleration_rate_hz;
  return blocks_.empty() ? 0.0
                         : blocks_.front().host_s -
                               (static_cast<double>(blocks_.front().first) - n) / description_.acceleration_rate_hz;
}

// Frame k of the session: the controller's frames interpolated at the device time that maps to the
// host time of acceleration sample k·r. False while the frames around that time have not arrived.
bool UsbRig::next_frame(SensorFrame& out) {
  const double n = static_cast<double>(frames_made_) * samples_per_frame_;
  if (blocks_.empty() || n >= static_cast<double>(acceleration_first_ + acceleration_.size())) return false;
  if (received_.size() < 2) return false;
  const double host = host_time_of_sample(n);
  const double device_us = usb_clock_.device_time(host) * 1e6;
  while (received_.size() >= 2 && static_cast<double>(received_[1].device_time_us) <= device_us)
    received_.pop_front();
  if (received_.size() < 2) return false;  // the frame after that time has not arrived yet
  const SensorFrame& a = received_[0];
  const SensorFrame& b = received_[1];
  const double span = static_cast<double>(b.device_time_us) - static_cast<double>(a.device_time_us);
  const double u = span > 0 ? std::clamp((device_us - static_cast<double>(a.device_time_us)) / span, 0.0, 1.0) : 0.0;
  const auto mix = [u](float x, float y) { return static_cast<float>(x + u * (y - x)); };
  out = SensorFrame{};
  out.sequence = static_cast<std::uint32_t>(frames_made_);
  out.device_time_us = static_cast<std::uint64_t>(std::max(0.0, device_us));
  out.host_ns = static_cast<std::int64_t>(host * 1e9);
  out.speed_m_s = mix(a.speed_m_s, b.speed_m_s);
  out.normal_force_N = mix(a.normal_force_N, b.normal_force_N);
  out.tangential_force_N = mix(a.tangential_force_N, b.tangential_force_N);
  out.flags = static_cast<std::uint16_t>(a.flags | b.flags);
  return true;
}

bool UsbRig::read(RigData& into, std::chrono::milliseconds wait) {
  if (!started_) throw std::logic_error("USB rig: read() before start()");
  const auto until = std::chrono::steady_clock::now() + wait;
  for (;;) {
    drain_frames();
    drain_acceleration();
    SensorFrame frame;
    std::size_t made = 0;
    while (frames_made_ < frames_total_ && next_frame(frame)) {
      into.frames.push_back(frame);
      if (frame.flags & (kNormalForceSaturated | kTangentialForceSaturated)) ++health_.saturated_frames;
      if (frame.flags & (kEncoderFault | kMotorFault | kWatchdogStopped | kForceFault)) ++health_.fault_frames;
      ++frames_made_;
      ++made;
    }
    // The acceleration that belongs with the frames made so far goes out with them.
    const auto samples_end = static_cast<std::uint64_t>(std::floor(static_cast<double>(frames_made_) * samples_per_frame_));
    if (samples_end > acceleration_first_) {
      const std::size_t count = static_cast<std::size_t>(std::min<std::uint64_t>(samples_end - acceleration_first_, acceleration_.size()));
      into.acceleration.insert(into.acceleration.end(), acceleration_.begin(),
                               acceleration_.begin() + static_cast<std::ptrdiff_t>(count));
      acceleration_.erase(acceleration_.begin(), acceleration_.begin() + static_cast<std::ptrdiff_t>(count));
      acceleration_first_ += count;
      health_.acceleration_samples += count;
    }
    health_.frames = frames_made_;
    const usb::UsbRigStatus status = controller_->status();
    health_.connected = status.connected;
    if (frames_made_ >= frames_total_) {
      health_.ended_because = "profile finished";
      return false;
    }
    if (!status.connected) {
      health_.ended_because = "the rig controller was unplugged (" + status.last_fault + ")";
      return false;
    }
    if (!status.device_fault.empty()) {
      health_.ended_because = status.device_fault;
      return false;
    }
    if (stopped_) {
      health_.ended_because = "stopped";
      return false;
    }
    if (made > 0 || std::chrono::steady_clock::now() >= until) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

void UsbRig::stop() {
  if (stopped_) return;
  stopped_ = true;
  try {
    controller_->stop();
  } catch (const std::exception&) {
    // Unplugged: the device's watchdog stops the motor by itself (PROTOCOL.md).
  }
}

RigHealth UsbRig::health() const {
  RigHealth h = health_;
  const usb::UsbRigStatus status = controller_->status();
  h.dropped_frames = status.frames_dropped;
  // The two mappings' scatter: the controller's frames about their fitted clock, and the audio
  // callbacks' stamps about theirs (an upper bound: each block uses its own stamp).
  const double usb = usb_clock_.residual_s(), audio = input_->clock().residual_s();
  h.alignment_error_ms = 1e3 * std::sqrt(usb * usb + audio * audio);
  return h;
}

}  // namespace nibrig::rig
