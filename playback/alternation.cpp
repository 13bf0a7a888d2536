#include "playback/alternation.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace nibrig::playback {

void play_in_turn(LiveAudition& audition, const Alternation& alternation,
                  const AlternationEvents& events) {
  if (!(alternation.seconds > 0.0) || !std::isfinite(alternation.seconds))
    throw std::invalid_argument("alternation: the time to play must be positive");
  if (!(alternation.switch_every > 0.0) || !std::isfinite(alternation.switch_every))
    throw std::invalid_argument("alternation: the time between switches must be positive");
  const std::size_t slots = audition.names().size();
  const auto start = std::chrono::steady_clock::now();
  double next_switch = alternation.switch_every;
  bool reported_loss = false;
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    audition.pump();
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (t >= alternation.seconds) break;
    if (slots > 1 && t >= next_switch) {
      audition.select((audition.selected() + 1) % slots);
      next_switch += alternation.switch_every;
      if (events.switched) events.switched(t, audition.selected());
    }
    const auto status = audition.output_status();
    if (status == OutputStatus::lost && !reported_loss) {
      if (events.device_lost) events.device_lost(t, audition.last_problem());
      reported_loss = true;
    } else if (status == OutputStatus::running) {
      reported_loss = false;
    }
  }
}

}  // namespace nibrig::playback
