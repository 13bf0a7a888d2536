// The round trip of an audio chain (output, actuator or cable, input) from impulses played at known
// frames and found again in the recording. Pure computation: the live measurement
// (round_trip_run.hpp) hands in what was played and what came back.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace nibrig::playback {

// The impulse: a maximum-length sequence of 255 samples (±level). Its autocorrelation is 255 at lag
// 0 and −1 elsewhere, so a correlation with the recording peaks at one sample, and its flat
// spectrum survives a band-limited chain (an actuator, an AC-coupled input) better than one click.
std::vector<double> round_trip_pulse(double level);

struct ImpulseSearch {
  // Lags tried after each impulse's frame, 0 to max_lag_samples: the round trip must be shorter
  // than the gap to the next impulse, or that one would be found instead.
  std::size_t max_lag_samples = 0;
  // An impulse counts as found where |normalised correlation| with the pulse reaches this (1 is a
  // scaled copy; noise alone gives about 1/√255 ≈ 0.06). Below it the impulse is missing: counted,
  // never averaged in. The sign is ignored, as an inverted chain (an accelerometer mounted the
  // other way) still has its delay.
  double threshold = 0.5;
};

struct FoundImpulse {
  std::size_t lag_samples = 0;  // from the frame it was played at to the best match in the input
  double correlation = 0.0;     // |normalised correlation| at that lag
};

// For each impulse played at frames `played_at` (in the recording's own sample count, the same
// clock), the lag at which `pulse` matches `recorded` best, or nullopt when its best match stays
// below the threshold or the recording ends before the whole search window. Throws
// std::invalid_argument for an empty pulse or a threshold outside (0, 1].
std::vector<std::optional<FoundImpulse>> find_impulses(std::span<const double> pulse,
                                                       std::span<const std::size_t> played_at,
                                                       std::span<const float> recorded,
                                                       const ImpulseSearch& search);

// The found lags summarised: missing impulses are counted, not averaged in.
struct RoundTripStats {
  std::size_t played = 0, found = 0;
  double mean_samples = 0.0;
  double stddev_samples = 0.0;  // sample standard deviation (n − 1); 0 with one impulse found
  std::size_t min_samples = 0, worst_samples = 0;
  double weakest_correlation = 0.0;  // the lowest |correlation| among the impulses found
};

RoundTripStats summarise_round_trips(std::span<const std::optional<FoundImpulse>> found);

}  // namespace nibrig::playback
