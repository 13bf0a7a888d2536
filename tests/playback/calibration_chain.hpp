// A simulated actuator chain with a closed-form response, shared by the calibration tests: a
// voice-coil actuator as a 2nd-order mechanical resonance times the accelerometer's AC coupling (a
// 2nd-order Butterworth high-pass), simulated by bilinear-transformed biquads.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace nibrig::playback::testing {

struct ChainModel {
  double gain = 20.0;  // m/s² per unit output at the resonance
  double resonance_hz = 120.0;
  double q = 3.0;
  double high_pass_hz = 10.0;
  // A notch (analogue 2nd order, zeros on the jω axis) when notch_hz > 0.
  double notch_hz = 0.0;
  double notch_q = 5.0;
};

// The analogue response at f: K·(ω0/Q)s/(s² + (ω0/Q)s + ω0²) · s²/(s² + √2 ωh s + ωh²) [· notch].
std::complex<double> analogue_response(const ChainModel& chain, double frequency_hz);

// The chain simulated at `sample_rate_hz`: x → x + cubic·x³ → biquads → delay, plus white noise of
// standard deviation noise_rms (seeded). Output has the input's length.
std::vector<double> simulate(const ChainModel& chain, const std::vector<double>& input,
                             double sample_rate_hz, std::size_t delay_samples, double cubic,
                             double noise_rms, unsigned seed);

}  // namespace nibrig::playback::testing
