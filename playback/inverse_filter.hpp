// The actuator's inverse filter: a minimum-phase FIR that flattens a measured chain over the
// rendered band (20-500 Hz) by regularised inversion, designed at the engine's internal rate. It
// turns requested acceleration (m/s²) into output level (full scale = 1).
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

#include "playback/measured_response.hpp"

namespace nibrig::playback {

struct InverseFilterSettings {
  double sample_rate_hz = 4000.0;  // the engine's internal rate: 2 to 8 kHz
  std::size_t taps = 256;
  double band_low_hz = 20.0, band_high_hz = 500.0;
  // In the band G = C*/(|C|² + β), β = in_band_regularisation·median(|C|²).
  double in_band_regularisation = 1e-3;
  // Outside the band the chain's roll-off is not inverted: |G| keeps its band-edge value, shaped by
  // a first-order high-pass below the band and low-pass above it (normalised to 1 at the edges).
  // Gentle shapes on purpose: a steep one makes a long, slowly ringing minimum-phase response that
  // 256 taps at 4 kHz would truncate, spilling ripple over the whole band.
  double low_corner_hz = 5.0;
  double high_corner_hz = 1000.0;
  // |G| is capped this far above its in-band median; where the cap bites the chain is not
  // flattened.
  double max_boost_db = 20.0;
};

struct FrequencyRange {
  double low_hz = 0.0, high_hz = 0.0;
};

struct InverseFilter {
  double sample_rate_hz = 0.0;
  std::vector<double> taps;  // output level per m/s² of requested acceleration
  // On the design grid (fs/M spacing, M ≥ 32·taps) over the band, from the chain's interpolated
  // magnitude and the taps' exact response: max |20·log10|C·G||, and its RMS.
  double max_deviation_db = 0.0;
  double rms_deviation_db = 0.0;
  // The largest gain of the taps relative to their in-band median, in dB, anywhere up to Nyquist.
  double max_boost_db = 0.0;
  // Where the regularised inverse reached the cap (empty when it never did).
  std::vector<FrequencyRange> boost_limited;
  double group_delay_100hz_s = 0.0;
};

// Throws std::invalid_argument when the settings are out of range (rate outside 2-8 kHz, band not
// below Nyquist, fewer than 16 taps) or the response does not cover the band, has fewer than two
// points, frequencies not strictly increasing, or a zero or non-finite value.
InverseFilter design_inverse_filter(const FrequencyResponse& chain,
                                    const InverseFilterSettings& settings);

// Σ taps[n]·e^(−j2πfn/fs): the FIR's exact response.
std::complex<double> fir_response(std::span<const double> taps, double frequency_hz,
                                  double sample_rate_hz);
// −dφ/dω of the FIR at f, in seconds: Re(Σ n·h[n]·e^(−jωn) / Σ h[n]·e^(−jωn)) / fs.
double fir_group_delay_s(std::span<const double> taps, double frequency_hz, double sample_rate_hz);

}  // namespace nibrig::playback
