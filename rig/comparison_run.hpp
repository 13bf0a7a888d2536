// A live comparison as a whole: a rig runs its profile into a session (rig/capture.hpp) while the
// simulation of a tool, driven by the measured speed and force (rig/live_simulation.hpp), runs
// beside it, and both streams go to the analysis (rig/live_comparison.hpp), whose table and
// waterfall rows a face shows as they come and reports at the end. Every face that compares a
// tool with its simulation on a rig runs it here.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "model/design/tool_sound.hpp"
#include "model/measure/threshold_curve.hpp"
#include "rig/capture.hpp"
#include "rig/live_comparison.hpp"

namespace nibrig::rig {

class LiveComparison;

struct ComparisonRunOptions {
  CaptureOptions capture;  // where the session goes, what is mounted, cancel
  LiveComparisonSettings analysis;  // its rates are set from the rig
  std::uint64_t seed = 1;           // the simulation's forcing noise
  // Called on the capture's thread with the measured frames as they arrive (e.g. the actuator
  // following the turntable, rig/contact_follower.hpp). May be empty.
  std::function<void(const RigData&)> on_data;
  // Called about ten times a second on the capture's thread with the running analysis: a face
  // takes new rows and the table from it (never waiting on the analysis thread). May be empty.
  std::function<void(LiveComparison&)> on_update;
};

struct ComparisonRun {
  CaptureResult capture;
  ComparisonTable table;  // the final one
  WaterfallRows rows;     // every row of the run, for the report's figure (unless on_update took them)
  std::string simulated;  // the simulated tool's name
  LiveComparisonSettings settings;  // as run (rates from the rig)
};

// Runs the comparison to the end of the profile (or a cancel, an unplug). Throws what
// capture_session throws, before any folder exists for a bad profile.
ComparisonRun run_comparison(Rig& rig, const SpeedProfile& profile,
                             const model::design::ToolSound& simulated,
                             const model::measure::ThresholdCurve& threshold,
                             const ComparisonRunOptions& options);

}  // namespace nibrig::rig
