#include "rig/pen/pen_play.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

#include "rig/pen/pen_clock.hpp"

namespace nibrig::rig::pen {

PenPlayStats play_pen(playback::LiveAudition& audition, PenStylus& stylus, double seconds,
                      std::stop_token stop, PenPlayEvents events) {
  // A turn per millisecond: well inside a 133-200 Hz pen's report interval, and a wait of half a
  // millisecond on average added to each contact's way to the engine.
  constexpr auto kTurn = std::chrono::milliseconds(1);
  PenPlayStats stats;
  double total_post_s = 0.0;
  const double start = pen_clock_now_s();
  while (!stop.stop_requested()) {
    const double now = pen_clock_now_s();
    if (seconds > 0 && now - start >= seconds) break;
    stylus.tick();
    if (const auto contact = stylus.take()) {
      audition.set_contact(contact->speed_m_s, contact->force_n);
      const double waited = std::max(0.0, pen_clock_now_s() - contact->time_s);
      ++stats.contacts;
      total_post_s += waited;
      stats.max_post_s = std::max(stats.max_post_s, waited);
    }
    audition.pump();
    for (const auto& note : stylus.take_strokes()) {
      if (note.began) ++stats.strokes;
      if (events.stroke) events.stroke(note);
    }
    if (stylus.removed()) {
      stats.tablet_removed = true;
      // The stroke's end was the last contact; it is posted above before the loop ends.
      if (const auto contact = stylus.take()) audition.set_contact(contact->speed_m_s, contact->force_n);
      for (const auto& note : stylus.take_strokes()) {
        if (events.stroke) events.stroke(note);
      }
      if (events.removed) events.removed();
      break;
    }
    std::this_thread::sleep_for(kTurn);
  }
  if (stats.contacts > 0) stats.mean_post_s = total_post_s / static_cast<double>(stats.contacts);
  return stats;
}

}  // namespace nibrig::rig::pen
