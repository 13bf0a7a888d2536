// The output settings the playback tests open on their private JACK server, and the search that
// lines a recording up with the offline render of the same signal.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "playback/audio_output.hpp"

namespace nibrig::playback::testing {

// The `system` device of the test server, unconnected so that each test wires the graph itself.
inline OutputSettings jack_settings(const std::string& stream_name, unsigned output_channel = 1) {
  OutputSettings s;
  s.api = "jack";
  s.device = "system";
  s.sample_rate = 48000;
  s.period_frames = 64;
  s.output_channel = output_channel;
  s.stream_name = stream_name;
  s.connect_ports = false;
  return s;
}

// Where `window` (length `length`) occurs in `reference`, when it occurs exactly once.
inline std::optional<std::size_t> locate(const std::vector<float>& reference, const float* window,
                                         std::size_t length) {
  std::optional<std::size_t> found;
  for (std::size_t at = 0; at + length <= reference.size(); ++at) {
    std::size_t i = 0;
    while (i < length && reference[at + i] == window[i]) ++i;
    if (i < length) continue;
    if (found) return std::nullopt;  // twice: the signal repeated, the match says nothing
    found = at;
  }
  return found;
}

}  // namespace nibrig::playback::testing
