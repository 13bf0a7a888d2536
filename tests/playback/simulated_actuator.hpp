// A voice-coil actuator with an accelerometer on it, as a JACK client: what it receives on its
// input port it returns on its output port through a resonance (a bilinear-transformed 2nd-order
// band-pass, 20 m/s² per unit at 120 Hz, Q 3), so that calibration can run against a real JACK
// graph and be checked against the filter's exact digital response.
#pragma once

#include <jack/jack.h>

#include <complex>
#include <string>

namespace nibrig::playback::testing {

class SimulatedActuator {
 public:
  // Registers "<name>:in" and "<name>:out" on the default server and activates.
  explicit SimulatedActuator(const std::string& name);
  ~SimulatedActuator();
  SimulatedActuator(const SimulatedActuator&) = delete;
  SimulatedActuator& operator=(const SimulatedActuator&) = delete;

  // True when the ports are connected, by this call or before it (jack_connect's EEXIST).
  bool connect(const std::string& source, const std::string& destination);
  // The exact response of the simulated chain at f (Hz): b(z)/a(z) at z = e^{j2πf/fs}.
  std::complex<double> response(double frequency_hz) const;

 private:
  static int process(jack_nframes_t frames, void* self) noexcept;

  jack_client_t* client_ = nullptr;
  jack_port_t *in_ = nullptr, *out_ = nullptr;
  double rate_ = 48000;
  double b0_ = 0, b1_ = 0, b2_ = 0, a1_ = 0, a2_ = 0;
  double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;
};

}  // namespace nibrig::playback::testing
