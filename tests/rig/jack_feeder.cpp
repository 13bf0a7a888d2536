#include "tests/rig/jack_feeder.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace nibrig::rig::testing {

JackFeeder::JackFeeder(const std::string& name, double amplitude, double frequency_hz)
    : name_(name), amplitude_(amplitude) {
  jack_status_t status{};
  client_ = jack_client_open(name.c_str(),
                             static_cast<jack_options_t>(JackNoStartServer | JackUseExactName), &status);
  if (client_ == nullptr)
    throw std::runtime_error("JackFeeder: cannot open JACK client '" + name + "'");
  phase_step_ = 2.0 * std::numbers::pi * frequency_hz / jack_get_sample_rate(client_);
  port_ = jack_port_register(client_, "out", JACK_DEFAULT_AUDIO_TYPE, JackPortIsOutput, 0);
  if (port_ == nullptr || jack_set_process_callback(client_, &JackFeeder::process, this) != 0 ||
      jack_activate(client_) != 0) {
    jack_client_close(client_);
    throw std::runtime_error("JackFeeder: cannot set up client '" + name + "'");
  }
}

JackFeeder::~JackFeeder() { jack_client_close(client_); }

bool JackFeeder::connect(const std::string& destination) {
  return jack_connect(client_, port().c_str(), destination.c_str()) == 0;
}

std::int64_t JackFeeder::frames_to_time_us(jack_nframes_t frame) const {
  return static_cast<std::int64_t>(jack_frames_to_time(client_, frame));
}

std::int64_t JackFeeder::now_us() const { return static_cast<std::int64_t>(jack_get_time()); }

double JackFeeder::sample_rate() const { return jack_get_sample_rate(client_); }

int JackFeeder::process(jack_nframes_t frames, void* self) noexcept {
  auto& f = *static_cast<JackFeeder*>(self);
  const auto entered = std::chrono::steady_clock::now().time_since_epoch();
  auto* out = static_cast<float*>(jack_port_get_buffer(f.port_, frames));
  for (jack_nframes_t i = 0; i < frames; ++i) {
    out[i] = static_cast<float>(f.amplitude_ * std::sin(f.phase_));
    f.phase_ += f.phase_step_;
    if (f.phase_ > 2.0 * std::numbers::pi) f.phase_ -= 2.0 * std::numbers::pi;
  }
  const std::int64_t entered_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(entered).count();
  const std::int64_t due = f.impulse_due_ns_.load();
  if (due != 0 && entered_ns >= due) {
    f.impulse_due_ns_.store(0);
    f.impulse_requested_.store(true);
  }
  if (f.impulse_requested_.exchange(false)) {
    out[0] = 1.0f;
    f.impulse_frame_.store(jack_last_frame_time(f.client_));
    f.impulse_host_ns_.store(std::chrono::duration_cast<std::chrono::nanoseconds>(entered).count());
  }
  return 0;
}

}  // namespace nibrig::rig::testing
