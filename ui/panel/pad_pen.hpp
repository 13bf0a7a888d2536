// The pad's pen: a tablet found in the background (and looked for again every few seconds while
// there is none, or after it is unplugged), then read as the stylus that drives the engine
// (rig::pen::PenStylus). The pad asks it each frame; without one, the pad draws with the mouse.
#pragma once

#include <memory>
#include <string>

#include "rig/pen/pen_stylus.hpp"
#include "ui/panel/background_job.hpp"

namespace nibrig::ui::panel {

class PadPen {
 public:
  PadPen() = default;
  ~PadPen();

  // Each frame, on the UI thread: takes a tablet the search found, drops one that went away, and
  // starts the next search when it is time.
  void poll(double now_s);
  // A stylus to use now (a test's, or the search's).
  void use(std::unique_ptr<rig::pen::PenStylus> stylus);
  // Stops looking for tablets (a test that drives the pad with the mouse only).
  void stop_looking() { looking_ = false; }

  rig::pen::PenStylus* stylus() { return stylus_.get(); }
  // What the pad says about the pen: the tablet and whether the force is from the default curve,
  // or why the mouse is drawing.
  const std::string& status() const { return status_; }

 private:
  std::unique_ptr<rig::pen::PenStylus> stylus_;
  std::unique_ptr<BackgroundJob<std::unique_ptr<rig::pen::PenStylus>>> search_;
  double next_search_s_ = 0.0;
  bool looking_ = true;
  std::string status_ = "looking for a pen tablet; drawing with the mouse";
};

}  // namespace nibrig::ui::panel
