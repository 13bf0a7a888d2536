// An A/B or triplet presentation heard in turn: the tools in a LiveAudition's slots, each for a
// while, round and round, for a given time. The audition is loaded, moved and opened by the
// caller; this only switches slots on time and reports what happened.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "playback/live_audition.hpp"

namespace nibrig::playback {

struct Alternation {
  double seconds = 0.0;       // how long to play
  double switch_every = 2.0;  // seconds between switches to the next slot
};

struct AlternationEvents {
  std::function<void(double t_s, std::size_t slot)> switched;               // the slot now heard
  std::function<void(double t_s, const std::string& problem)> device_lost;  // once per loss
};

// Plays for `alternation.seconds` from the call, switching slot every `switch_every` seconds
// (never with one slot); returns then. Hands the audition's pending commands over every 50 ms, so
// it needs no other pump(). Throws std::invalid_argument for a time or period that is not positive.
void play_in_turn(LiveAudition& audition, const Alternation& alternation,
                  const AlternationEvents& events = {});

}  // namespace nibrig::playback
