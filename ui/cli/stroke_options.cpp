#include "ui/cli/stroke_options.hpp"

#include <stdexcept>

#include "model/io/paper_drawing.hpp"

namespace nibrig::ui::cli {
namespace {

// Owns the inner source and overrides its force.
class WithForce final : public rt::SpeedSource {
 public:
  WithForce(std::unique_ptr<rt::SpeedSource> inner, double force)
      : inner_(std::move(inner)), force_(force) {}
  double speed_at(double t) const noexcept override { return inner_->speed_at(t); }
  double force_at(double) const noexcept override { return force_; }

 private:
  std::unique_ptr<rt::SpeedSource> inner_;
  double force_;
};

}  // namespace

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

Stroke make_stroke(const StrokeOptions& o) {
  Stroke stroke;
  if (o.speed_mm_s >= 0) {
    stroke.source = std::make_unique<rt::ConstantSpeed>(o.speed_mm_s / 1000.0);
    stroke.description = "constant " + std::to_string(o.speed_mm_s).substr(0, 6) + " mm/s";
    stroke.natural_seconds = 5.0;
  } else if (!o.trajectory.empty()) {
    const auto drawing = model::io::read_paper_drawing(o.trajectory);
    auto source = std::make_unique<rt::TrajectorySpeed>(drawing);
    stroke.natural_seconds = source->duration();
    stroke.source = std::move(source);
    stroke.description = "trajectory " + o.trajectory.filename().string();
  } else {
    stroke.source = std::make_unique<rt::SweepSpeed>();
    stroke.description = "sweep 17-250 mm/s, 3 s period";
    stroke.natural_seconds = 2 * rt::SweepSpeed::kPaperPeriod;
  }
  if (o.force_n >= 0) {
    stroke.source = std::make_unique<WithForce>(std::move(stroke.source), o.force_n);
    stroke.description += ", " + std::to_string(o.force_n).substr(0, 5) + " N";
  }
  return stroke;
}

}  // namespace nibrig::ui::cli
