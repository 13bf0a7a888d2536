// Audio output to a device chosen by name: renders an rt::BlockRenderer into one output channel,
// optionally captures one input channel into a lock-free ring, counts xruns, and survives the
// loss of its device (a JACK server killed, an interface unplugged) by reopening it by name.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "playback/capture_stamp.hpp"
#include "rt/block_renderer.hpp"

namespace nibrig::playback {

struct OutputSettings {
  std::string api;     // "jack", "alsa", "pulse" (any case); empty: first API with an output device
  std::string device;  // exact name or a unique case-insensitive part of it; empty: the default
  unsigned sample_rate = 48000;             // Hz; JACK runs only at its server's rate
  unsigned period_frames = 256;             // a request: JACK uses its server's period
  unsigned output_channel = 1;              // 1-based; every other output channel gets silence
  std::optional<unsigned> input_channel;    // 1-based; set to capture that input channel
  std::size_t capture_capacity = 1u << 17;  // samples the capture ring holds (~2.7 s at 48 kHz)
  std::string stream_name = "nibrig";       // the JACK client name: distinct per instance
  bool connect_ports = true;  // JACK: connect to the device's ports (false: leave unconnected)
  std::chrono::milliseconds retry_interval{200};  // how often a lost device is looked for
  std::chrono::milliseconds stall_timeout{1000};  // no callback for this long counts as a loss
  // The device to capture from, by the same rule as `device`; empty: `device` itself. Another
  // device runs on its own clock unless the back end links the two.
  std::string input_device;
};

// What was actually opened (a back end may round the period; JACK imposes its own).
struct StreamInfo {
  std::string api;
  std::string device;
  unsigned sample_rate = 0;
  unsigned period_frames = 0;
  unsigned output_channels = 0;  // of the device, all opened
  unsigned input_channels = 0;   // of the input device; 0 when not capturing
  long latency_frames = 0;       // as RtAudio reports it
  std::string input_device;      // the device captured from; empty when not capturing
};

enum class OutputStatus {
  running,  // the stream runs and the renderer is called
  lost,     // the device went away; it is looked for every retry_interval
};

struct OutputStats {
  std::uint64_t callbacks = 0;
  std::uint64_t frames = 0;
  std::uint64_t output_underflows = 0;  // callbacks flagged RTAUDIO_OUTPUT_UNDERFLOW
  std::uint64_t input_overflows = 0;    // callbacks flagged RTAUDIO_INPUT_OVERFLOW
  std::uint64_t capture_dropped = 0;    // captured samples lost because the ring was full
  std::uint64_t losses = 0;             // times the device was lost
  std::uint64_t reconnects = 0;         // times it was reopened after a loss
};

class AudioOutput {
 public:
  // Chooses the device, opens and starts the stream; from then on `renderer` is called on the
  // audio thread until destruction (it must outlive this object). Throws DeviceError naming what
  // was asked when the device is missing, busy, lacks the channel or the sample rate.
  AudioOutput(rt::BlockRenderer& renderer, OutputSettings settings);
  // Stops and closes the stream, whatever state it is in (running, lost, being reopened).
  ~AudioOutput();
  AudioOutput(const AudioOutput&) = delete;
  AudioOutput& operator=(const AudioOutput&) = delete;

  OutputStatus status() const noexcept;
  OutputStats stats() const noexcept;
  StreamInfo stream_info() const;
  // Why the device was last lost or could not be reopened; empty while nothing went wrong.
  std::string last_problem() const;

  // Captured input samples, oldest first: up to `max` into `out`; returns how many. One control
  // thread only (the ring has a single consumer). Nothing is captured without input_channel.
  std::size_t read_captured(float* out, std::size_t max) noexcept;
  std::size_t captured_available() const noexcept;
  // When the captured samples arrived (output_callback.hpp), oldest first: up to `max` into
  // `out`; returns how many. The same single consumer as read_captured.
  std::size_t read_capture_stamps(CaptureStamp* out, std::size_t max) noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace nibrig::playback
