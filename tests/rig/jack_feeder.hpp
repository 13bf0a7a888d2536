// A bare libjack client that plays a known signal into the JACK graph: the rig tests' stand-in for
// an accelerometer on an interface input. A sine of known amplitude, and on request one impulse at
// the start of the first cycle after a moment, whose JACK frame time it records so that a test
// knows on the host clock when the impulse was "sampled".
#pragma once

#include <jack/jack.h>

#include <atomic>
#include <cstdint>
#include <string>

namespace nibrig::rig::testing {

class JackFeeder {
 public:
  // Client `name` with one output port "out"; a sine of `amplitude` (full scale) at `frequency_hz`.
  JackFeeder(const std::string& name, double amplitude, double frequency_hz);
  ~JackFeeder();
  JackFeeder(const JackFeeder&) = delete;
  JackFeeder& operator=(const JackFeeder&) = delete;

  std::string port() const { return name_ + ":out"; }
  bool connect(const std::string& destination);
  // The next cycle starts with an impulse of 1.0 instead of the sine's sample.
  void impulse() { impulse_requested_.store(true); }
  // The first cycle processed at or after host time `host_s` (steady clock) starts with an impulse.
  void impulse_at(double host_s) { impulse_due_ns_.store(static_cast<std::int64_t>(host_s * 1e9)); }
  // The JACK frame time of the cycle that carried the impulse (0 until then).
  jack_nframes_t impulse_frame() const { return impulse_frame_.load(); }
  // The host's steady clock (s) when the cycle carrying the impulse was processed: when the
  // impulse entered the graph, the truth a capture's time base is checked against.
  double impulse_host_s() const { return impulse_host_ns_.load() * 1e-9; }
  // JACK's clock (µs) at a frame time, and now: the same clock as std::chrono::steady_clock's.
  std::int64_t frames_to_time_us(jack_nframes_t frame) const;
  std::int64_t now_us() const;
  double sample_rate() const;

 private:
  static int process(jack_nframes_t frames, void* self) noexcept;
  std::string name_;
  jack_client_t* client_ = nullptr;
  jack_port_t* port_ = nullptr;
  double amplitude_, phase_step_, phase_ = 0.0;
  std::atomic<bool> impulse_requested_{false};
  std::atomic<std::int64_t> impulse_due_ns_{0};
  std::atomic<jack_nframes_t> impulse_frame_{0};
  std::atomic<std::int64_t> impulse_host_ns_{0};
};

}  // namespace nibrig::rig::testing
