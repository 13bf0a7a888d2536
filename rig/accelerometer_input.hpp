// The rig's accelerometer, on an input of an audio interface chosen by name: an RtAudio stream
// (playback::AudioOutput, whose output plays silence unless the same interface drives the actuator)
// captures one channel into a lock-free ring; the capture thread drains it and puts the samples on
// the host clock with the callbacks' stamps (rig/clock_fit.hpp). Samples stay in full-scale
// units; times `m_s2_per_full_scale` they are m/s² (the figure `nibrig calibrate --accelerometer`
// takes), written into every session as its calibration.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "playback/audio_output.hpp"
#include "rig/clock_fit.hpp"
#include "rt/block_renderer.hpp"

namespace nibrig::rig {

// What a rig's accelerometer reads at full scale unless calibrated: a ±5 g part on a line input.
inline constexpr double kDefaultAccelerometerM_s2 = 5 * 9.81;

// The stream an accelerometer is captured on unless told otherwise: input channel 1 of the
// default device, under its own JACK client name.
playback::OutputSettings accelerometer_stream();

struct AccelerometerSettings {
  // The audio stream it is read on: api, device (by name), rate, period, JACK client name; its
  // input_channel is the accelerometer's (1-based).
  playback::OutputSettings stream = accelerometer_stream();
  double m_s2_per_full_scale = kDefaultAccelerometerM_s2;
  // The converter's latency, from the sample's instant to the audio graph; unset: what the back end
  // reports for the device's capture port. Set it from a measurement, or to 0 for a source patched
  // straight into the stream's port (a JACK client, as in the tests), which no converter delays.
  std::optional<double> device_latency_s;
};

class AccelerometerInput {
 public:
  // Opens and starts the stream. Throws playback::DeviceError naming what was asked and what
  // exists, std::invalid_argument for a scale that is not positive or a stream with no input
  // channel.
  explicit AccelerometerInput(const AccelerometerSettings& settings);
  ~AccelerometerInput();

  // Appends the samples captured since the last call (full-scale units) and takes their stamps
  // into the clock. Capture thread only.
  std::size_t read(std::vector<float>& into);
  // The index the next sample read has in host_time_of: the samples read so far and those the
  // full ring dropped while nobody read.
  std::uint64_t samples_read() const { return samples_read_; }
  // Host time (s, steady clock) at which sample `index` (counted from the stream's first) was
  // captured: the stamp of the callback that delivered it, less the latency the stamps do not
  // include. Call it as samples are read (it knows the last few hundred callbacks). The stamp of
  // the very block, not a line through many: a clock that wanders with the machine's load (JACK's
  // dummy driver) makes a line fitted over seconds miss by milliseconds, while a crystal's drift of
  // tens of ppm is nothing within one block.
  double host_time_of(double index) const;
  // The stamps fitted as a clock: the interface's drift against the host, and how much the stamps
  // scatter about it (reported with a capture).
  const ClockFit& clock() const { return clock_; }
  // The two parts of the latency host_time_of takes off: RtAudio's buffering (a callback sees input
  // one period after JACK delivered it) and the device's capture latency as its back end reports it
  // (JACK: the latency of system:capture, from the converter to the graph).
  double buffering_s() const { return buffering_s_; }
  double device_latency_s() const { return device_latency_s_; }
  double sample_rate() const { return rate_; }
  double m_s2_per_full_scale() const { return settings_.m_s2_per_full_scale; }
  std::string device_name() const;
  playback::OutputStats stats() const { return stream_->stats(); }

 private:
  struct Silence final : rt::BlockRenderer {
    void render(float* out, std::size_t frames) noexcept override {
      for (std::size_t i = 0; i < frames; ++i) out[i] = 0.0f;
    }
  };
  AccelerometerSettings settings_;
  Silence silence_;
  std::unique_ptr<playback::AudioOutput> stream_;
  ClockFit clock_;
  std::uint64_t samples_read_ = 0;  // delivered, plus those the full ring dropped before them
  std::uint64_t samples_delivered_ = 0;
  double rate_ = 0.0, buffering_s_ = 0.0, device_latency_s_ = 0.0;
  std::vector<float> buffer_;
  std::vector<playback::CaptureStamp> stamps_;
  std::vector<playback::CaptureStamp> recent_;
};

}  // namespace nibrig::rig
