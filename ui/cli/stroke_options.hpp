// The options render and audition share: which tool on which surface, through which stylus, and
// how the stylus moves (constant speed, the rig's sweep, or an artist's recorded drawing).
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/design/tool_sound.hpp"
#include "rt/stroke_request.hpp"

namespace nibrig::ui::cli {

struct StrokeOptions {
  // A catalog tool id, or a design point ("DM85:0.5,vero:0.5,tip=2mm") to predict
  // (model/design/tool_sound.hpp).
  std::string tool, surface;
  std::filesystem::path catalog, design;
  std::filesystem::path forcing_model;  // for design points; empty: fit the catalog first
  std::optional<double> speed_mm_s;  // constant speed
  bool sweep = false;
  std::filesystem::path trajectory;
  std::optional<double> force_n;  // constant normal force; none: 2.2 N (or the trajectory's)
  unsigned seed = 1;
};

void add_stroke_options(CLI::App* cmd, StrokeOptions& o);

// What the engine will do with a --speed or --force outside what the paper measured (17-250 mm/s
// at 2.2 N), one line each: the values are played, but clamped or extrapolated, and the user is
// told so before any work starts. Empty when both are inside or not given.
std::vector<std::string> outside_measured_range(const StrokeOptions& o);

// The stroke the options describe (exactly one of --speed, --sweep, --trajectory; none = --sweep).
rt::Stroke make_stroke(const StrokeOptions& o);

// Where the tools' sounds come from: --catalog, --design and --forcing.
model::design::ToolSoundOptions tool_sound_options(const StrokeOptions& o);

}  // namespace nibrig::ui::cli
