// A bare libjack client that records its input ports into preallocated buffers: the playback
// tests' independent ear on the JACK graph. It shares nothing with RtAudio except the server, and
// stamps what it records with the server's frame clock so delays can be measured.
#pragma once

#include <jack/jack.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace nibrig::playback::testing {

class JackRecorder {
 public:
  // Opens client `name` on the default server (JACK_DEFAULT_SERVER), registers input ports
  // in_1..in_<ports> and activates. Recording starts with `start`; until then it only watches.
  JackRecorder(const std::string& name, std::size_t ports, std::size_t capacity_frames);
  ~JackRecorder();
  JackRecorder(const JackRecorder&) = delete;
  JackRecorder& operator=(const JackRecorder&) = delete;

  std::string port_name(std::size_t input) const;  // "name:in_<input+1>"
  // jack_connect(source, this recorder's input); false when either port is not there.
  bool connect(const std::string& source, std::size_t input);
  // jack_connect between any two ports of the server, through this client.
  bool connect_ports(const std::string& source, const std::string& destination);

  void start() { recording_.store(true, std::memory_order_release); }
  // Waits until the buffers are full; false on timeout.
  bool wait_full(std::chrono::milliseconds timeout) const;
  std::size_t recorded() const { return recorded_.load(std::memory_order_acquire); }
  const std::vector<float>& samples(std::size_t input) const { return buffers_[input]; }
  // One JACK cycle of the recording: the server's frame time at its start and where its samples
  // begin in samples(…).
  struct Cycle {
    jack_nframes_t time = 0;
    std::size_t start = 0;
    std::size_t frames = 0;
    jack_time_t started_us = 0;  // when the cycle began, on JACK's clock (jack_get_cycle_times)
    // When this client's callback ran for the cycle, on CLOCK_MONOTONIC: after every client
    // upstream of it rendered the cycle, so nothing it hears was rendered later than this.
    double heard_monotonic_s = 0.0;
  };
  // The recorded cycles; read once the recording is full.
  std::vector<Cycle> cycles() const {
    return {cycles_.begin(), cycles_.begin() + cycle_count_.load(std::memory_order_acquire)};
  }
  // Frames, since activation, in which any input carried a non-zero sample.
  std::uint64_t nonsilent_frames() const { return nonsilent_.load(std::memory_order_acquire); }
  // Xruns the server reported to this client.
  std::uint64_t xruns() const { return xruns_.load(std::memory_order_acquire); }
  jack_client_t* client() const { return client_; }

 private:
  static int process(jack_nframes_t frames, void* self) noexcept;
  static int xrun(void* self) noexcept;

  std::string name_;
  jack_client_t* client_ = nullptr;
  std::vector<jack_port_t*> ports_;
  std::vector<std::vector<float>> buffers_;
  std::size_t capacity_;
  std::atomic<bool> recording_{false};
  std::atomic<std::size_t> recorded_{0};
  std::vector<Cycle> cycles_;  // preallocated: one per recorded cycle of at least 16 frames
  std::atomic<std::size_t> cycle_count_{0};
  std::atomic<std::uint64_t> nonsilent_{0};
  std::atomic<std::uint64_t> xruns_{0};
};

}  // namespace nibrig::playback::testing
