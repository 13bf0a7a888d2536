#include "ui/cli/stroke_options.hpp"

#include "ui/cli/forcing_options.hpp"

namespace nibrig::ui::cli {

void add_stroke_options(CLI::App* cmd, StrokeOptions& o) {
  cmd->add_option("--tool", o.tool,
                  "Tool id in the catalog (e.g. cryon, stab, vero2), or a design point to predict "
                  "(e.g. \"DM85:0.5,vero:0.5,tip=2mm\", with its own modes)")
      ->required();
  cmd->add_option("--surface", o.surface, "Surface id (e.g. office, note, stone, glass)")->required();
  cmd->add_option("--catalog", o.catalog, "Catalog JSON (default: the bundled one)");
  cmd->add_option("--forcing", o.forcing_model,
                  "Forcing model for design points (`nibrig forcing fit`; default: fit the "
                  "catalog first)");
  cmd->add_option("--design", o.design,
                  "Stylus design JSON whose modes shape the vibration (default: assets/designs/"
                  "stylus_vero_tip2mm.json)");
  auto* speed = cmd->add_option("--speed", o.speed_mm_s, "Constant tip speed in mm/s");
  auto* sweep = cmd->add_flag("--sweep", o.sweep, "The rig's sweep, 17 -> 250 mm/s, 3 s period");
  auto* trajectory = cmd->add_option(
      "--trajectory", o.trajectory,
      "An artist's drawing (piovarci2018/drawing/*.csv[.gz]): its speed and force, looped");
  speed->excludes(sweep)->excludes(trajectory);
  sweep->excludes(trajectory);
  cmd->add_option("--force", o.force_n, "Constant normal force in N (default 2.2, the paper's)");
  cmd->add_option("--seed", o.seed, "Seed of the forcing noise (same seed, same samples)");
}

rt::Stroke make_stroke(const StrokeOptions& o) {
  rt::StrokeRequest request;
  if (o.speed_mm_s >= 0) request.speed_m_s = o.speed_mm_s / 1000.0;
  request.trajectory = o.trajectory;
  if (o.force_n >= 0) request.force_n = o.force_n;
  return rt::make_stroke(request);
}

model::design::ToolSoundOptions tool_sound_options(const StrokeOptions& o) {
  return {o.catalog, o.design, o.forcing_model, design_progress()};
}

}  // namespace nibrig::ui::cli
