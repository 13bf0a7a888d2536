#include "rig/loop_print_capture.hpp"

#include <filesystem>
#include <stdexcept>

#include "model/design/design_search.hpp"
#include "model/numeric/cancellation.hpp"

namespace nibrig::rig {

namespace fs = std::filesystem;

namespace {

// A session that is not the round's measurement, kept beside it: <folder>-<why>-<k>.
fs::path kept_aside(const fs::path& folder, const std::string& why) {
  for (int k = 1;; ++k) {
    fs::path kept = folder;
    kept += "-" + why + "-" + std::to_string(k);
    if (!fs::exists(kept)) return kept;
  }
}

// The replay rig's recordings of the round's print.
void replay_the_print(RigRequest& request, const std::vector<RecordedPrint>& prints,
                      const model::design::DesignPoint& design) {
  for (const auto& p : prints)
    if (model::design::same_design(p.design, design)) {
      request.replay = p.vibration;
      request.replay_friction = p.friction;
      return;
    }
  throw std::invalid_argument("the replay rig has no recording of the print " +
                              model::design::label(design));
}

}  // namespace

LoopCaptureOptions replay_recorded_prints(const fs::path& folder,
                                          const model::design::LoopRequest& loop, double speedup) {
  LoopCaptureOptions c;
  c.rig.kind = RigKind::replay;
  c.rig.speedup = speedup;
  c.recorded_prints =
      find_recorded_prints(folder, loop.surface, {loop.first_material, loop.second_material});
  c.profile.clear();  // a replay runs what was recorded
  return c;
}

LoopCapture measure_loop_round(model::design::LoopSession& session,
                               const LoopCaptureOptions& options) {
  const auto round = session.awaiting_measurement();
  if (!round) throw std::logic_error("no round of the design loop awaits a measurement");
  const fs::path folder = model::design::round_session_folder(session.folder(), *round);
  LoopCapture out{*round, std::nullopt};
  if (!fs::exists(folder)) {
    fs::path partial = folder;
    partial += ".partial";
    if (fs::exists(partial)) fs::rename(partial, kept_aside(folder, "interrupted"));
    RigRequest request = options.rig;
    request.tool = model::design::to_string(session.rounds().back().design);
    request.surface = session.request().surface;
    if (request.kind == RigKind::replay)
      replay_the_print(request, options.recorded_prints, session.rounds().back().design);
    model::design::ToolSounds sounds(options.sounds);
    OpenedRig opened =
        open_rig_with_profile(request, sounds, options.profile, "steps", options.seconds);
    CaptureOptions capture;
    capture.folder = folder;
    capture.tool = request.tool;
    capture.surface = request.surface;
    capture.notes = "design loop round " + std::to_string(*round);
    capture.cancel = options.cancel;
    capture.on_progress = options.on_progress;
    out.capture = capture_session(*opened.rig, opened.profile, capture);
    if (!out.capture->complete) {
      const fs::path kept = kept_aside(folder, "ended-early");
      fs::rename(out.capture->folder, kept);
      throw std::runtime_error("the print's capture ended early (" +
                               out.capture->record.ended_because + "): its session is kept in " +
                               kept.string() + "; round " + std::to_string(*round) +
                               " still awaits its measurement");
    }
  }
  session.take_measurement(session.analyse_session(folder));
  return out;
}

void drive_design_loop(model::design::LoopSession& session,
                       const std::optional<LoopCaptureOptions>& capture, const LoopStepDone& done,
                       std::stop_token cancel) {
  const auto report = [&](LoopStep step, int round) {
    if (done) done(step, round);
  };
  for (;;) {
    if (cancel.stop_requested()) throw model::numeric::Cancelled("the design loop");
    if (const auto waiting = session.awaiting_measurement()) {
      const fs::path captured = model::design::round_session_folder(session.folder(), *waiting);
      if (fs::exists(captured) && !capture) {
        session.take_measurement(session.analyse_session(captured));
      } else if (capture) {
        measure_loop_round(session, *capture);
      } else {
        report(LoopStep::waiting, *waiting);
        return;
      }
      report(LoopStep::measured, *waiting);
      continue;
    }
    const auto next = session.advance();
    if (!next) {
      report(LoopStep::stopped, 0);
      return;
    }
    report(LoopStep::proposed, *next);
  }
}

}  // namespace nibrig::rig
