#include "ui/cli/stroke_options.hpp"

#include <fmt/format.h>

#include <cmath>

#include "playback/offline_render.hpp"
#include "rt/reference_load.hpp"
#include "ui/cli/forcing_options.hpp"
#include "ui/options/number_checks.hpp"

namespace nibrig::ui::cli {

void add_stroke_options(CLI::App* cmd, StrokeOptions& o) {
  cmd->add_option("--tool", o.tool,
                  "Tool id in the catalog (e.g. cryon, stab, vero2), or a design point to predict "
                  "(e.g. \"DM85:0.5,vero:0.5,tip=2mm\", with its own modes)")
      ->required();
  cmd->add_option("--surface", o.surface, "Surface id (e.g. office, note, stone, glass)")->required();
  cmd->add_option("--catalog", o.catalog, "Catalog JSON (default: the bundled one)");
  cmd->add_option("--forcing", o.forcing_model,
                  "Forcing model for design points (`nibrig forcing fit`; default: the "
                  "catalog's, cached)");
  cmd->add_option("--design", o.design,
                  "Stylus design JSON whose modes shape the vibration (default: assets/designs/"
                  "stylus_vero_tip2mm.json)");
  // Set through a function so that "not given" is an empty optional: no typed value can mean it.
  // The ranges are playback's (offline_render.hpp), which every face's stroke is held to.
  auto* speed = cmd->add_option_function<double>(
                       "--speed", [&o](const double& v) { o.speed_mm_s = v; },
                       "Constant tip speed in mm/s (measured: 17-250)")
                    ->check(off_or_in_range(1e3 * playback::kSlowestStrokeM_s, 1e3 * playback::kFastestStrokeM_s,
                                            "a speed in mm/s"));
  auto* sweep = cmd->add_flag("--sweep", o.sweep, "The rig's sweep, 17 -> 250 mm/s, 3 s period");
  auto* trajectory = cmd->add_option(
      "--trajectory", o.trajectory,
      "An artist's drawing (piovarci2018/drawing/*.csv[.gz]) or a pen stroke recorded in its "
      "format: its speed and force, looped");
  speed->excludes(sweep)->excludes(trajectory);
  sweep->excludes(trajectory);
  cmd->add_option_function<double>(
         "--force", [&o](const double& v) { o.force_n = v; },
         fmt::format("Constant normal force in N (default {:g}, the paper's)",
                     rt::kReferenceNormalForce))
      ->check(off_or_in_range(playback::kLightestStrokeN, playback::kHeaviestStrokeN,
                              "a normal force in N"));
  cmd->add_option("--seed", o.seed, "Seed of the forcing noise (same seed, same samples)")
      ->check(any_seed());
}

rt::Stroke make_stroke(const StrokeOptions& o) {
  rt::StrokeRequest request;
  if (o.speed_mm_s) request.speed_m_s = *o.speed_mm_s / 1000.0;
  request.trajectory = o.trajectory;
  request.force_n = o.force_n;
  return rt::make_stroke(request);
}

model::design::ToolSoundOptions tool_sound_options(const StrokeOptions& o) {
  return {o.catalog, o.design, o.forcing_model, design_progress()};
}

std::vector<std::string> outside_measured_range(const StrokeOptions& o) {
  constexpr double low = 1000 * rt::SweepStroke::kPaperLow, high = 1000 * rt::SweepStroke::kPaperHigh;
  std::vector<std::string> notes;
  // What rt::ForcingGenerator does outside its table's speeds (forcing_generator.hpp).
  if (o.speed_mm_s && *o.speed_mm_s > high)
    notes.push_back(fmt::format(
        "--speed {:g} mm/s is above the measured {:g}-{:g} mm/s: the vibration is held at the "
        "tool's fastest measured speed (clamped; the summary counts the samples)",
        *o.speed_mm_s, low, high));
  else if (o.speed_mm_s && *o.speed_mm_s == 0)
    notes.push_back("--speed 0 mm/s: the tip is at rest, so the tool is silent");
  else if (o.speed_mm_s && *o.speed_mm_s < low)
    notes.push_back(fmt::format(
        "--speed {:g} mm/s is below the measured {:g}-{:g} mm/s: the vibration is the slowest "
        "measured speed's, faded linearly toward silence at rest (extrapolated)",
        *o.speed_mm_s, low, high));
  const double reference = rt::kReferenceNormalForce;
  const double cap = rt::kMaxNormalForceRatio * reference;
  if (o.force_n && *o.force_n == 0)
    notes.push_back("--force 0 N: the tip is lifted, so the tool is silent");
  else if (o.force_n && *o.force_n > cap)
    notes.push_back(fmt::format(
        "--force {:g} N: the paper measured at {:g} N only; the vibration grows with force up to "
        "{:g} N and is clamped there",
        *o.force_n, reference, cap));
  else if (o.force_n && std::abs(*o.force_n - reference) > 1e-9)
    notes.push_back(fmt::format(
        "--force {:g} N: the paper measured at {:g} N only; the vibration is scaled by force / "
        "{:g} N, an assumption (rt/forcing_generator.hpp)",
        *o.force_n, reference, reference));
  return notes;
}

}  // namespace nibrig::ui::cli
