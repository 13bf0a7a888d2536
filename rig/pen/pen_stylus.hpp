// The pen as the stylus of a live engine: the tablet read (PenInput), each report turned into a
// contact with the pen's pressure curve (PenContact), and the newest contact kept for the thread
// that owns the engine to post (playback::LiveAudition is one thread's). The faces' one call for
// "play the engine from this pen": `nibrig audition --pen` and the panel's pad.
//
// Threads: the reader's thread delivers; take(), tick(), trace() and take_strokes() are for the
// engine's control thread (the CLI's loop, the panel's UI thread), which never waits for the reader
// longer than a copy under a mutex.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "rig/pen/pen_contact.hpp"
#include "rig/pen/pen_force_file.hpp"
#include "rig/pen/pen_input.hpp"

namespace nibrig::rig::pen {

struct PenStrokeNote {
  std::uint64_t stroke = 0;
  bool began = false;  // else it ended, for `why`
  PenStrokeEnd why = PenStrokeEnd::tip_up;
  double time_s = 0.0;
};

// Where the tip touched, for a face to draw the strokes.
struct PenPathPoint {
  std::uint64_t stroke = 0;
  double x_m = 0.0, y_m = 0.0;  // from the tablet's top-left corner
};

class PenStylus {
 public:
  // Opens the tablet (PenInput's name rules) with the curve stored for `pen_name`, or for the
  // tablet's name when that is empty, else the default. Throws what PenInput and pen_curve_for
  // throw.
  PenStylus(const std::string& tablet, const std::string& pen_name = {});
  ~PenStylus();
  PenStylus(const PenStylus&) = delete;
  PenStylus& operator=(const PenStylus&) = delete;

  const TabletInfo& tablet() const;
  const PenCurveChoice& curve() const { return curve_; }
  bool removed() const;

  // The newest contact since the last call, if any (post it to the engine).
  std::optional<PenContactSample> take();
  // Call now and then (each control-loop turn or frame): a pen held still reaches speed 0.
  void tick();
  // Strokes begun and ended since the last call.
  std::vector<PenStrokeNote> take_strokes();
  // The points the tip touched since the last call (at most the last few thousand).
  std::vector<PenPathPoint> take_path();
  // The last contacts (oldest first), at most `count`, for a face's traces.
  std::vector<PenContactSample> trace(std::size_t count) const;
  PenContactStatus status() const { return contact_.status(); }
  // Every report as the reader gave it, for whoever records strokes; set before drawing starts.
  void on_sample(std::function<void(const PenSample&, double force_n)> listener);

 private:
  PenCurveChoice curve_;
  PenContact contact_;
  mutable std::mutex mutex_;
  std::optional<PenContactSample> newest_;
  std::deque<PenContactSample> trace_;
  std::vector<PenStrokeNote> strokes_;
  std::deque<PenPathPoint> path_;
  std::function<void(const PenSample&, double)> listener_;
  std::unique_ptr<PenInput> input_;  // last: its thread stops first
};

}  // namespace nibrig::rig::pen
