// The exponential sine sweep of actuator calibration (Farina 2000) and the estimate of the chain's
// complex frequency response, delay and per-frequency SNR from what was played and what the
// accelerometer recorded. Pure computation: the live measurement hands in the two buffers.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "playback/measured_response.hpp"

namespace nibrig::playback {

struct SineSweepSettings {
  double sample_rate_hz = 48000.0;
  // Well beyond the 20-500 Hz band on both sides: the edges of the sweep are faded and unreliable,
  // and a sweep reaching far above the band makes the impulse response sharp enough to place the
  // chain's delay to the sample.
  double start_hz = 10.0;
  double end_hz = 20000.0;
  double duration_s = 4.0;  // of one sweep, fades included
  double level = 0.3;       // peak output level, full scale = 1
  double fade_s = 0.05;     // raised-cosine fade in and out
  // After each sweep, to capture the chain's tail and the interface's latency.
  double silence_s = 1.0;
  // Sweeps played back to back; two or more give a per-frequency SNR from their spread.
  int repetitions = 2;
};

// Throws std::invalid_argument naming the setting at fault (end at or above Nyquist, fades longer
// than half the sweep, level outside (0, 1], ...).
void validate(const SineSweepSettings& settings);

std::size_t sine_sweep_samples(
    const SineSweepSettings& settings);                         // one sweep, without its silence
std::size_t period_samples(const SineSweepSettings& settings);  // one sweep and its silence

// The whole signal to play: `repetitions` × (sweep, silence), peak `level`. The sweep is
// x(t) = sin(2π f1 L (e^(t/L) − 1)), L = T / ln(f2/f1), so its instantaneous frequency rises from
// f1 to f2 exponentially and every harmonic k of the chain's distortion arrives a fixed time
// L·ln(k) earlier than the linear response after deconvolution.
std::vector<double> exponential_sine_sweep(const SineSweepSettings& settings);

struct EstimationSettings {
  double pre_onset_s = 0.005;  // kept before the onset: the band-limited response's leading edge
  // The chain's impulse response is taken to have decayed within this; it must be shorter than the
  // silence and than the lead of the 2nd harmonic's product.
  double impulse_length_s = 0.3;
  // The onset (the delay) is the first sample, up to 10 ms before the impulse response's peak,
  // whose magnitude reaches this fraction of the peak's.
  double onset_threshold = 0.3;
  double points_per_octave = 24.0;  // of the returned log-spaced grid
  // Tikhonov term of Y·X*/(|X|² + ε), relative to max |X|²: negligible where the sweep has energy,
  // and it keeps the division from amplifying noise where it has none.
  double regularisation = 1e-6;
};

struct ResponseEstimate {
  // The chain's response with its delay taken out (its phase is relative to the onset), in
  // recorded units per played unit, on a log-spaced grid over the part of the sweep not faded.
  FrequencyResponse response;
  // Per frequency: |mean|² over the variance of the mean across repetitions, in dB; empty with a
  // single repetition. It counts everything that differs between repetitions (noise, drift), not a
  // bias common to all (the distortion at the fundamental).
  std::vector<double> snr_db;
  std::size_t delay_samples = 0;  // onset of the impulse response: the interface's latency and more
  double delay_s = 0.0;
  std::size_t peak_lag_samples = 0;  // lag of the impulse response's largest magnitude
  // How far before the onset the 2nd and 3rd harmonics' products lie (they are windowed out).
  double harmonic2_lead_s = 0.0, harmonic3_lead_s = 0.0;
  // The first sweep's windowed impulse response, from pre_onset_s before the onset.
  std::vector<double> impulse_response;
};

// played: what exponential_sine_sweep(settings) returned (as scaled and played); recorded: the
// accelerometer, same rate, starting at the same instant as played, at least as long (extra samples
// are ignored). Throws std::invalid_argument on sizes, settings, or a delay that leaves too little
// of the silence for the impulse response.
ResponseEstimate estimate_response(const SineSweepSettings& settings,
                                   std::span<const double> played, std::span<const double> recorded,
                                   const EstimationSettings& estimation = {});

}  // namespace nibrig::playback
