// Playing the engine from a pen: the control loop between the pen (PenStylus) and the engine's live
// contact (playback::LiveAudition, a one-thread object): every millisecond it posts the newest
// contact, lets a held pen fall still, and hands strokes to the face. What `nibrig audition --pen`
// runs; a test runs it without the face.
#pragma once

#include <cstdint>
#include <functional>
#include <stop_token>

#include "playback/live_audition.hpp"
#include "rig/pen/pen_stylus.hpp"

namespace nibrig::rig::pen {

struct PenPlayEvents {
  std::function<void(const PenStrokeNote&)> stroke;  // a stroke began or ended
  std::function<void()> removed;                     // the tablet went away; the loop ends
};

struct PenPlayStats {
  std::uint64_t contacts = 0;  // posted to the engine
  std::uint64_t strokes = 0;
  // From a report's kernel stamp to its post: libinput, the reader's thread and this loop's turn.
  double mean_post_s = 0.0, max_post_s = 0.0;
  bool tablet_removed = false;
};

// Runs on the calling thread (the audition's control thread) until `seconds` have passed (0: no
// limit), `stop` is requested, or the tablet is removed.
PenPlayStats play_pen(playback::LiveAudition& audition, PenStylus& stylus, double seconds,
                      std::stop_token stop = {}, PenPlayEvents events = {});

}  // namespace nibrig::rig::pen
