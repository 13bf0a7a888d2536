// The options render and audition share: which tool on which surface, through which stylus, and
// how the stylus moves (constant speed, the rig's sweep, or an artist's recorded drawing).
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <string>

#include "rt/speed_source.hpp"

namespace nibrig::ui::cli {

struct StrokeOptions {
  // A catalog tool id, or a design point ("DM85:0.5,vero:0.5,tip=2mm") to predict (tool_voice.hpp).
  std::string tool, surface;
  std::filesystem::path catalog, design;
  std::filesystem::path forcing_model;  // for design points; empty: fit the catalog first
  double speed_mm_s = -1;  // constant speed; < 0 = not given
  bool sweep = false;
  std::filesystem::path trajectory;
  double force_n = -1;  // constant normal force; < 0 = the paper's 2.2 N (or the trajectory's)
  unsigned seed = 1;
};

void add_stroke_options(CLI::App* cmd, StrokeOptions& o);

// The source the options describe (exactly one of --speed, --sweep, --trajectory; none = --sweep),
// and a line saying what it is, for the summary.
struct Stroke {
  std::unique_ptr<rt::SpeedSource> source;
  std::string description;
  double natural_seconds;  // one sweep period ×2, the trajectory's length, or 5 s
};
Stroke make_stroke(const StrokeOptions& o);

}  // namespace nibrig::ui::cli
