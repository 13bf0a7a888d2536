#include "rig/comparison_start.hpp"

#include <utility>

#include "model/io/bundled_assets.hpp"
#include "model/measure/threshold_curve.hpp"
#include "rig/comparison_report.hpp"

namespace nibrig::rig {

namespace {
constexpr const char* kDefaultComparisonProfile =
    "sweep";  // the study's: the speeds a stroke crosses
}

ComparisonStart::ComparisonStart(ComparisonRequest request) : request_(std::move(request)) {
  check_rig_request(request_.rig);
  asked_profile_ =
      profile_to_run(request_.rig, request_.profile, kDefaultComparisonProfile, request_.seconds);
}

ComparisonStart::ComparisonStart(ComparisonStart&&) noexcept = default;
ComparisonStart& ComparisonStart::operator=(ComparisonStart&&) noexcept = default;
ComparisonStart::~ComparisonStart() = default;

void ComparisonStart::open() {
  rig_sounds_ = std::make_unique<model::design::ToolSounds>(request_.sounds);
  OpenedRig opened = open_rig_running(request_.rig, *rig_sounds_, asked_profile_, request_.seconds);
  const RigDescription& described = opened.rig->description();
  const SimulatedChoice choice = simulated_choice(
      described, request_.simulate.empty() ? request_.rig.tool : request_.simulate,
      request_.simulate_surface.empty() ? request_.rig.surface : request_.simulate_surface);
  if (request_.simulation_sounds)
    simulation_sounds_ = std::make_unique<model::design::ToolSounds>(*request_.simulation_sounds);
  model::design::ToolSounds& sounds = simulation_sounds_ ? *simulation_sounds_ : *rig_sounds_;
  try {
    sounds.check(choice.tool, choice.surface);
  } catch (const RigRequestRefused&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw RigRequestRefused(RigRequestRefused::Field::simulate, e.what());
  }
  simulated_ = sounds.sound(choice.tool, choice.surface);
  measured_tool_ = request_.rig.tool.empty() ? described.tool : request_.rig.tool;
  surface_ = choice.surface;
  rig_ = std::move(opened.rig);
  profile_ = std::move(opened.profile);
}

ComparisonRun ComparisonStart::run(const ComparisonHooks& hooks) {
  ComparisonRunOptions options;
  options.capture.folder = request_.session;
  options.capture.tool = request_.rig.tool;
  options.capture.surface = request_.rig.surface;
  options.capture.cancel = hooks.cancel;
  options.capture.on_progress = hooks.on_progress;
  options.on_data = hooks.on_data;
  options.on_update = hooks.on_update;
  options.seed = request_.seed;
  const auto threshold = model::measure::ThresholdCurve::load(model::io::default_threshold_curve());
  return run_comparison(*rig_, *profile_, simulated_, threshold, options);
}

model::io::ComparisonFile ComparisonStart::report(const ComparisonRun& run) const {
  return comparison_report(measured_tool_, surface_, run.table, run.settings);
}

RigComparison compare_on_rig(ComparisonRequest request, const ComparisonHooks& hooks) {
  ComparisonStart start(std::move(request));
  start.open();
  RigComparison out;
  out.run = start.run(hooks);
  out.report = start.report(out.run);
  out.simulated_modes = start.simulated().modes;
  return out;
}

}  // namespace nibrig::rig
