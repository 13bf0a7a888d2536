// The rig's part of a design loop: the awaiting round's print run on a rig (simulated, USB) into
// round-N/session, analysed and taken into the loop (model/design/loop_session.hpp). A capture
// killed midway leaves its session.partial, and one stopped early a short session: each is kept
// beside (session-interrupted-K, session-ended-early-K) and the print captured again; a session
// complete but not yet analysed is analysed, not captured.
#pragma once

#include <functional>
#include <optional>
#include <stop_token>
#include <string>

#include "model/design/loop_session.hpp"
#include "model/design/tool_sound.hpp"
#include "rig/capture.hpp"
#include "rig/recorded_prints.hpp"
#include "rig/rig_request.hpp"

namespace nibrig::rig {

struct LoopCaptureOptions {
  RigRequest rig;  // which rig and how; its tool and surface are set to the round's print
  // The replay rig's prints: the round's print is its recordings replayed (rig.replay is set to
  // them), so its loop proposes only these (LoopRequest::candidates).
  std::vector<RecordedPrint> recorded_prints;
  // The simulated rig's print: a design point played with this forcing model (a lab's stored one
  // or a file, standing for the prints as made); empty: the loop's starting model.
  model::design::ToolSoundOptions sounds;
  std::string profile = "steps";
  std::optional<double> seconds;
  std::stop_token cancel;
  std::function<void(const CaptureProgress&)> on_progress;
};

struct LoopCapture {
  int round = 0;
  std::optional<CaptureResult> capture;  // none: a session already captured was analysed
};

// The options that measure each print by replaying its recordings found under `folder` for the
// loop's surface and materials (find_recorded_prints; throws what it throws), `speedup` as a
// replay's.
LoopCaptureOptions replay_recorded_prints(const std::filesystem::path& folder,
                                          const model::design::LoopRequest& loop, double speedup);

// Throws std::logic_error when no round awaits a measurement, std::invalid_argument when the replay
// rig has no recording of the round's print, what opening the rig and capturing throw, and
// std::runtime_error when the capture ended before its profile did (the session is kept and the
// round still awaits its measurement).
LoopCapture measure_loop_round(model::design::LoopSession& session,
                               const LoopCaptureOptions& options);

// What drive_design_loop did, as it does it.
enum class LoopStep { proposed, measured, waiting, stopped };
using LoopStepDone = std::function<void(LoopStep step, int round)>;

// Runs the loop on as far as it goes here: a round awaiting its print is measured (its captured
// session analysed, or with `capture` the print captured first), then the next is proposed, until
// the loop stops (`stopped`, round 0) or a round awaits a print nobody here can measure (`waiting`:
// no rig given and no session captured). Each step is reported when done. `cancel` (also the
// capture's) ends it between steps with model::numeric::Cancelled. Throws what the steps throw.
void drive_design_loop(model::design::LoopSession& session,
                       const std::optional<LoopCaptureOptions>& capture, const LoopStepDone& done,
                       std::stop_token cancel = {});

}  // namespace nibrig::rig
