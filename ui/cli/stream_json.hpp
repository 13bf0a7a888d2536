// What a command that played or measured through an audio device found, as JSON for
// `--json FILE`: the stream it opened, the engine's and the device's counters, round trips.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "playback/audio_output.hpp"
#include "playback/round_trip_run.hpp"
#include "rt/engine_stats.hpp"

namespace nibrig::ui::cli {

nlohmann::json stream_json(const playback::StreamInfo& stream);
nlohmann::json engine_stats_json(const rt::EngineStats& stats);
nlohmann::json output_stats_json(const playback::OutputStats& stats);
// One entry per period measured; a round trip with no impulse found is null, not 0.
nlohmann::json round_trips_json(const std::vector<playback::RoundTripResult>& results);

}  // namespace nibrig::ui::cli
