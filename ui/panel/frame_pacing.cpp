#include "ui/panel/frame_pacing.hpp"

namespace nibrig::ui::panel {

void FramePacing::before_frame(PanelWindow& window, double wait_s) {
  waited_ = false;
  const bool skipped = window.frames_skipped() != skipped_seen_;
  skipped_seen_ = window.frames_skipped();
  const bool moving = wait_s <= 0.0 || settle_ < kSettleFrames;
  if (moving) {
    if (wait_s <= 0.0) settle_ = 0;
    else ++settle_;
    const double left =
        kFramePeriod_s - std::chrono::duration<double>(std::chrono::steady_clock::now() - last_frame_).count();
    if (skipped && left > 0.0 && window.wait_events(left)) settle_ = 0;
  } else {
    waited_ = true;
    if (window.wait_events(wait_s)) settle_ = 0;
  }
  last_frame_ = std::chrono::steady_clock::now();
}

}  // namespace nibrig::ui::panel
