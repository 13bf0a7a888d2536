// A stroke as a person asks for it — a constant speed, the rig's sweep or an artist's recorded
// trajectory, with the paper's normal force or another — made into the source the engine fills its
// blocks from, with a line that says what it is and how long it naturally lasts. Every face that
// plays a tool makes its strokes here. Runs on a control thread: it may read a file and throw.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "rt/stroke_source.hpp"

namespace nibrig::rt {

struct StrokeRequest {
  std::optional<double> speed_m_s;   // a constant speed
  std::filesystem::path trajectory;  // else an artist's drawing (piovarci2018/drawing/*.csv[.gz])
                                     // else the rig's sweep, 17-250 mm/s with a 3 s period
  std::optional<double> force_n;     // a constant normal force; none: the paper's 2.2 N (or the
                                     // trajectory's recorded force)
};

struct Stroke {
  std::unique_ptr<StrokeSource> source;
  std::string description;  // "sweep 17-250 mm/s, 3 s period, 1.50 N"
  double natural_seconds;   // two sweep periods, the trajectory's length, or 5 s
};

// Throws std::invalid_argument for a negative or non-finite speed or force, and what the drawing
// reader throws for a bad trajectory file.
Stroke make_stroke(const StrokeRequest& request);

}  // namespace nibrig::rt
