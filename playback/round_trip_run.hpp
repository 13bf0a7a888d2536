// Measuring the whole chain's round trip on a real device: impulses played through an output
// channel (the actuator, or a cable looped back) and found in an input channel of the same stream,
// so that both count frames on one clock. One measurement per period asked; each reports what it
// opened.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "playback/audio_output.hpp"
#include "playback/round_trip.hpp"

namespace nibrig::playback {

struct RoundTripSettings {
  // output_channel = the impulses' way out, input_channel (required) = their way back in; the
  // period is replaced by each of the periods asked.
  OutputSettings device;
  int impulses = 50;
  // From one impulse to the next: also the longest round trip that can be measured (less the
  // pulse's 255 samples), as each impulse is looked for only before the next is played.
  double interval_s = 0.25;
  double level = 0.25;     // the pulse's peak, full scale = 1
  double threshold = 0.5;  // ImpulseSearch::threshold
  // Silence before the first impulse once the stream runs (and the graph is wired).
  std::chrono::milliseconds lead_in{200};
  std::chrono::seconds timeout{60};  // per period, for the whole recording to arrive
  // Called once the stream is open and before any impulse is played: a test wires a JACK graph
  // here. It may throw, which ends the measurement.
  std::function<void(const StreamInfo&)> on_open;
};

struct RoundTripResult {
  StreamInfo stream;  // what was opened: the API, device, rate and the period the back end chose
  unsigned period_asked = 0;
  RoundTripStats stats;
  double mean_ms = 0.0, stddev_ms = 0.0, min_ms = 0.0, worst_ms = 0.0;
  std::vector<std::optional<FoundImpulse>> impulses;  // in the order played
  // The device's xruns while measuring (underflows and overflows): a round trip that moved with
  // one is explained by it.
  std::uint64_t xruns = 0;
};

// After each period's measurement (index, of how many, its result): a face's progress.
using RoundTripProgress =
    std::function<void(std::size_t done, std::size_t total, const RoundTripResult& last)>;

// One measurement per entry of `periods` (frames asked; empty: settings.device.period_frames).
// Throws DeviceError for the device; std::invalid_argument without an input channel or for
// settings out of range (naming the setting); std::runtime_error when the recording did not arrive
// within the timeout, the device was lost or the capture overflowed. A stop request ends it
// between impulses and returns the periods finished.
std::vector<RoundTripResult> measure_round_trips(const RoundTripSettings& settings,
                                                 const std::vector<unsigned>& periods = {},
                                                 const RoundTripProgress& progress = {},
                                                 std::stop_token stop = {});

}  // namespace nibrig::playback
