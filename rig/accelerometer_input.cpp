#include "rig/accelerometer_input.hpp"

#include <cmath>
#include <stdexcept>

namespace nibrig::rig {
namespace {

// The fitted clock (drift and scatter, reported) follows the last 2 s: 20 windows of 0.1 s.
constexpr double kClockWindow_s = 0.1;
constexpr std::size_t kClockWindows = 20;

}  // namespace

playback::OutputSettings accelerometer_stream() {
  playback::OutputSettings s;
  s.input_channel = 1;
  s.stream_name = "nibrig-rig-input";
  return s;
}

AccelerometerInput::AccelerometerInput(const AccelerometerSettings& settings)
    : settings_(settings), clock_(kClockWindow_s, kClockWindows) {
  if (!(settings.m_s2_per_full_scale > 0.0) || !std::isfinite(settings.m_s2_per_full_scale))
    throw std::invalid_argument("the accelerometer's m/s² per full scale must be positive");
  if (settings.device_latency_s &&
      (!(*settings.device_latency_s >= 0.0) || !std::isfinite(*settings.device_latency_s)))
    throw std::invalid_argument("the accelerometer's converter latency must be >= 0 s");
  if (!settings.stream.input_channel)
    throw std::invalid_argument("the accelerometer's stream has no input channel to capture");
  stream_ = std::make_unique<playback::AudioOutput>(silence_, settings.stream);
  const playback::StreamInfo info = stream_->stream_info();
  rate_ = info.sample_rate;
  // The callback sees input one period after its last sample was taken, and the back end reports
  // its own input latency on top (RtAudio: the port latency under JACK).
  buffering_s_ = static_cast<double>(info.period_frames) / rate_;
  device_latency_s_ = settings.device_latency_s
                          ? *settings.device_latency_s
                          : static_cast<double>(std::max(0L, info.latency_frames)) / rate_;
  buffer_.resize(8192);
  stamps_.resize(1024);
}

AccelerometerInput::~AccelerometerInput() = default;

std::size_t AccelerometerInput::read(std::vector<float>& into) {
  for (;;) {
    const std::size_t n = stream_->read_capture_stamps(stamps_.data(), stamps_.size());
    for (std::size_t i = 0; i < n; ++i) recent_.push_back(stamps_[i]);
    if (recent_.size() > 512) recent_.erase(recent_.begin(), recent_.end() - 256);
    for (std::size_t i = 0; i < n; ++i)
      clock_.add(static_cast<double>(stamps_[i].first_sample) / rate_,
                 static_cast<double>(stamps_[i].host_ns) * 1e-9);
    if (n < stamps_.size()) break;
  }
  std::size_t total = 0;
  for (;;) {
    const std::size_t n = stream_->read_captured(buffer_.data(), buffer_.size());
    into.insert(into.end(), buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(n));
    total += n;
    if (n < buffer_.size()) break;
  }
  samples_delivered_ += total;
  // The ring drops what arrives while it is full (~2.7 s: a reader that waited, as a USB rig does
  // between opening and starting), and the stamps count every sample the device sent: the next
  // sample's index counts the dropped ones too, or host_time_of would place everything after them
  // that many samples early (after a long wait, a whole capture before the motor's start). Read when
  // the ring is empty, the count holds for the next sample; during a capture the reader drains the
  // ring every few milliseconds and nothing is dropped.
  samples_read_ = samples_delivered_ + stream_->stats().capture_dropped;
  return total;
}

// A callback's stamp is when the block starting at first_sample was handed to us: one period after
// JACK's cycle carried it (RtAudio buffers a period), and that cycle carried what the converter
// took the device's capture latency earlier.
double AccelerometerInput::host_time_of(double index) const {
  for (auto it = recent_.rbegin(); it != recent_.rend(); ++it)
    if (static_cast<double>(it->first_sample) <= index)
      return static_cast<double>(it->host_ns) * 1e-9 +
             (index - static_cast<double>(it->first_sample)) / rate_ - buffering_s_ - device_latency_s_;
  // Older than every stamp kept: the fitted clock.
  return clock_.host_time(index / rate_) - buffering_s_ - device_latency_s_;
}

std::string AccelerometerInput::device_name() const {
  const auto info = stream_->stream_info();
  return info.api + " " + info.device + ", input " +
         std::to_string(*settings_.stream.input_channel);
}

}  // namespace nibrig::rig
