// When the panel draws a frame: at the display's rate while something moves, else only on input,
// with a timeout for the live readouts. An idle panel drawing at full rate kept half a core busy
// under Xvfb for a picture that did not change.
#pragma once

#include <chrono>
#include <cstddef>

#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel {

class FramePacing {
 public:
  // Frames drawn at once after input, before waiting again: ImGui shows a click's or hover's
  // effect a frame or two after the event.
  static constexpr int kSettleFrames = 3;
  // The display's period: a frame the window did not render (unchanged) was not paced by a swap,
  // so the next waits out the rest of it (input still ends the wait at once).
  static constexpr double kFramePeriod_s = 1.0 / 60.0;

  // Before each frame. `wait_s` is how long the panel may wait for input (Panel::idle_wait_s(): 0
  // while something moves): returns at once for 0 and for kSettleFrames after input (after the
  // rest of the period when the last frame was not rendered), else sleeps in the window's event
  // wait until input or the timeout.
  void before_frame(PanelWindow& window, double wait_s);
  // Whether the last frame followed an idle wait (the panel's benchmark counts them).
  bool waited() const { return waited_; }

 private:
  int settle_ = kSettleFrames;
  bool waited_ = false;
  std::size_t skipped_seen_ = 0;
  std::chrono::steady_clock::time_point last_frame_{};
};

}  // namespace nibrig::ui::panel
