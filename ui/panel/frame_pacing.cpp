#include "ui/panel/frame_pacing.hpp"

namespace nibrig::ui::panel {

void FramePacing::before_frame(PanelWindow& window, double wait_s) {
  waited_ = false;
  if (wait_s <= 0.0) {
    settle_ = 0;
    return;
  }
  if (settle_ < kSettleFrames) {
    ++settle_;
    return;
  }
  waited_ = true;
  if (window.wait_events(wait_s)) settle_ = 0;
}

}  // namespace nibrig::ui::panel
