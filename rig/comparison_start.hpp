// Comparing a tool with its simulation on a rig, the same for every face: the rig, its profile and
// the length checked before anything opens, the rig opened with its profile, the simulated tool
// chosen (the one asked, else the one mounted) and made, the run (rig/comparison_run.hpp) and its
// report. A face maps its options onto a ComparisonRequest and shows RigRequestRefused in its own
// words.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>

#include "model/design/tool_sound.hpp"
#include "model/io/comparison_file.hpp"
#include "rig/comparison_run.hpp"
#include "rig/rig_request.hpp"

namespace nibrig::rig {

struct ComparisonRequest {
  RigRequest rig;  // the rig and what is mounted on it
  // steps | sweep | a CSV file; empty: the study's sweep. A replayed rig runs what it recorded.
  std::string profile;
  std::optional<double> seconds;  // cuts or repeats the profile
  // What to simulate (a catalog id or design point) and on which surface; empty: what is mounted.
  std::string simulate, simulate_surface;
  // Where the simulated rig's tool and the simulation come from (empty: the bundled files).
  model::design::ToolSoundOptions sounds;
  // The simulation from other files than the simulated rig's tool; nullopt: the same.
  std::optional<model::design::ToolSoundOptions> simulation_sounds;
  std::filesystem::path
      session;             // the captured session's folder (<folder>.partial while recording)
  std::uint64_t seed = 1;  // the simulation's forcing noise
};

// What a face follows a run with; each may be empty (rig/comparison_run.hpp says on which thread).
struct ComparisonHooks {
  std::stop_token cancel;  // the motor stops and the session is finished with what it holds
  std::function<void(const CaptureProgress&)> on_progress;
  std::function<void(const RigData&)> on_data;
  std::function<void(LiveComparison&)> on_update;
};

// The start in its steps, for a face that does something between them (plays the simulation on
// the actuator once the rig is open): construct, open(), run(). compare_on_rig() is all of them.
class ComparisonStart {
 public:
  // Checks what needs no device and no catalog: the rig request, the length, and a named profile
  // (a CSV profile is read here). Throws RigRequestRefused; FormatError for a broken profile file.
  explicit ComparisonStart(ComparisonRequest request);
  ComparisonStart(ComparisonStart&&) noexcept;
  ComparisonStart& operator=(ComparisonStart&&) noexcept;
  ~ComparisonStart();

  // Opens the rig, chooses what to simulate and makes its sound (a design point's FEM: seconds;
  // `sound_options`' progress reports it). Throws RigRequestRefused (field simulate) for a tool the
  // catalog lacks or an unsaid one on a rig that does not know what is mounted; what open_rig
  // throws for a missing device or session.
  void open();

  // After open().
  Rig& rig() const { return *rig_; }
  const SpeedProfile& profile() const { return *profile_; }
  const model::design::ToolSound& simulated() const { return simulated_; }
  // The tool measured (the request's, else what the rig says is mounted) and the surface.
  const std::string& measured_tool() const { return measured_tool_; }
  const std::string& surface() const { return surface_; }

  // Runs the profile to its end (or a cancel, an unplug) into the request's session folder. Throws
  // what run_comparison throws.
  ComparisonRun run(const ComparisonHooks& hooks);
  // The run's table as the report (comparison.json).
  model::io::ComparisonFile report(const ComparisonRun& run) const;

 private:
  ComparisonRequest request_;
  std::optional<SpeedProfile> asked_profile_;  // as checked; nullopt: a replay runs its own
  std::unique_ptr<model::design::ToolSounds> rig_sounds_, simulation_sounds_;
  std::unique_ptr<Rig> rig_;
  std::optional<SpeedProfile> profile_;
  model::design::ToolSound simulated_;
  std::string measured_tool_, surface_;
};

struct RigComparison {
  ComparisonRun run;
  model::io::ComparisonFile report;
  std::string simulated_modes;  // whose modes shaped the simulated tool
};

// Checks, opens and runs in one call.
RigComparison compare_on_rig(ComparisonRequest request, const ComparisonHooks& hooks = {});

}  // namespace nibrig::rig
