#include "ui/panel/pad_pen.hpp"

namespace nibrig::ui::panel {
namespace {

// A search opens every input device once (libinput's enumeration): every few seconds is often
// enough to notice a tablet plugged in, and rare enough to cost nothing.
constexpr double kPadPenSearchEvery_s = 3.0;

std::string pad_pen_status(const rig::pen::PenStylus& stylus) {
  const auto& curve = stylus.curve();
  return "pen: \"" + stylus.tablet().name + "\"; force from " +
         (curve.is_default ? std::string("the default pressure curve (0-4.9 N; `nibrig pen calibrate` measures the pen's)")
                           : "its calibration " + curve.file.filename().string());
}

}  // namespace

PadPen::~PadPen() = default;

void PadPen::use(std::unique_ptr<rig::pen::PenStylus> stylus) {
  stylus_ = std::move(stylus);
  if (!stylus_) return;
  status_ = pad_pen_status(*stylus_);
  // A report wakes the window from its idle wait, so that the pen is followed even while nothing
  // else on screen moves.
  stylus_->on_sample([](const rig::pen::PenSample&, double) {
    if (auto wake = job_done_hook.load()) wake();
  });
}

void PadPen::poll(double now_s) {
  if (stylus_ && stylus_->removed()) {
    status_ = "the tablet \"" + stylus_->tablet().name + "\" was unplugged; drawing with the mouse";
    stylus_.reset();
    next_search_s_ = now_s + kPadPenSearchEvery_s;
  }
  if (search_ && search_->done()) {
    if (auto found = search_->take_result(); found && *found) {
      use(std::move(*found));
    } else if (!stylus_) {
      const std::string why = search_->error();
      status_ = (why.empty() ? std::string("no pen tablet") : why) + "; drawing with the mouse";
    }
    search_.reset();
    next_search_s_ = now_s + kPadPenSearchEvery_s;
  }
  if (!stylus_ && !search_ && looking_ && now_s >= next_search_s_) {
    search_ = std::make_unique<BackgroundJob<std::unique_ptr<rig::pen::PenStylus>>>(
        "looking for a pen tablet", [](JobControl&) { return std::make_unique<rig::pen::PenStylus>(""); });
  }
}

}  // namespace nibrig::ui::panel
