#include "tests/playback/simulated_actuator.hpp"

#include <cerrno>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace nibrig::playback::testing {

SimulatedActuator::SimulatedActuator(const std::string& name) {
  jack_status_t status{};
  client_ = jack_client_open(
      name.c_str(), static_cast<jack_options_t>(JackNoStartServer | JackUseExactName), &status);
  if (!client_) throw std::runtime_error("SimulatedActuator: cannot open JACK client " + name);
  rate_ = jack_get_sample_rate(client_);
  // K·(ω0/Q)s / (s² + (ω0/Q)s + ω0²) by the bilinear transform, prewarped at ω0.
  const double gain = 20.0, f0 = 120.0, q = 3.0;
  const double w0 = 2 * std::numbers::pi * f0;
  const double c = w0 / std::tan(w0 / (2 * rate_));
  const double bw = w0 / q;
  const double a0 = c * c + bw * c + w0 * w0;
  b0_ = gain * bw * c / a0;
  b1_ = 0;
  b2_ = -b0_;
  a1_ = (2 * w0 * w0 - 2 * c * c) / a0;
  a2_ = (c * c - bw * c + w0 * w0) / a0;
  in_ = jack_port_register(client_, "in", JACK_DEFAULT_AUDIO_TYPE, JackPortIsInput, 0);
  out_ = jack_port_register(client_, "out", JACK_DEFAULT_AUDIO_TYPE, JackPortIsOutput, 0);
  jack_set_process_callback(client_, &SimulatedActuator::process, this);
  if (!in_ || !out_ || jack_activate(client_) != 0) {
    jack_client_close(client_);
    throw std::runtime_error("SimulatedActuator: cannot start " + name);
  }
}

SimulatedActuator::~SimulatedActuator() { jack_client_close(client_); }

bool SimulatedActuator::connect(const std::string& source, const std::string& destination) {
  const int status = jack_connect(client_, source.c_str(), destination.c_str());
  return status == 0 || status == EEXIST;
}

std::complex<double> SimulatedActuator::response(double frequency_hz) const {
  const std::complex<double> zi = std::polar(1.0, -2 * std::numbers::pi * frequency_hz / rate_);
  return (b0_ + b1_ * zi + b2_ * zi * zi) / (1.0 + a1_ * zi + a2_ * zi * zi);
}

int SimulatedActuator::process(jack_nframes_t frames, void* self) noexcept {
  auto& a = *static_cast<SimulatedActuator*>(self);
  const auto* in = static_cast<const float*>(jack_port_get_buffer(a.in_, frames));
  auto* out = static_cast<float*>(jack_port_get_buffer(a.out_, frames));
  for (jack_nframes_t i = 0; i < frames; ++i) {
    const double x = in[i];
    const double y = a.b0_ * x + a.b1_ * a.x1_ + a.b2_ * a.x2_ - a.a1_ * a.y1_ - a.a2_ * a.y2_;
    a.x2_ = a.x1_, a.x1_ = x, a.y2_ = a.y1_, a.y1_ = y;
    out[i] = static_cast<float>(y);
  }
  return 0;
}

}  // namespace nibrig::playback::testing
