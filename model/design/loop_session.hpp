// A design loop as a session in its folder (loop_folder.hpp): opened new or resumed, it proposes a
// round (the design, its prediction and its print's files), takes the print's measurement (a rig
// session analysed as `catalog build` does, or a pairing measured elsewhere), refits, and proposes
// the next, until it stops (design_loop.hpp). Every face drives the same session: the command
// line, the panel, Python; the rig's capture of a round is rig/loop_print_capture.hpp.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/design/design_response_grid.hpp"
#include "model/design/loop_folder.hpp"
#include "model/design/loop_model.hpp"
#include "model/design/prediction_inputs.hpp"
#include "model/forcing/forcing_inputs.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/printer_profile.hpp"
#include "model/numeric/progress_counter.hpp"
#include "model/space/space_file.hpp"

namespace nibrig::model::design {

class LoopSession {
 public:
  // A new loop in `folder` with `request` (the folder must not hold a loop: resume that one), or
  // with no request the loop the folder holds, its measured rounds taken in again. Reads and checks
  // everything first (space, target, printer, catalog), then loads the model and the range's design
  // grid (from the user cache, else solved: tens of seconds, announced through `progress`). Throws
  // std::invalid_argument naming what is wrong (a target the space cannot place, a space without
  // a descriptor map, a request for a loop that exists), io::FormatError for a file that does not
  // read, and what the inputs' loading throws.
  static std::unique_ptr<LoopSession> open(const std::filesystem::path& folder,
                                           std::optional<LoopRequest> request,
                                           const numeric::StepProgress& progress = {});
  // The loop the folder holds, resumed with its round limit set to `max_rounds` (loop.json says
  // it from then on): a loop stopped at its old limit goes on. Throws as open does, and
  // std::invalid_argument for a limit below the rounds made or above kMostLoopRounds.
  static std::unique_ptr<LoopSession> resume_with_rounds(
      const std::filesystem::path& folder, int max_rounds,
      const numeric::StepProgress& progress = {});

  const std::filesystem::path& folder() const { return folder_; }
  const LoopRequest& request() const { return request_; }
  const std::vector<LoopRoundRecord>& rounds() const { return rounds_; }
  double threshold() const { return loop_->setup().threshold; }

  // The last round, when its print has not been measured yet.
  std::optional<int> awaiting_measurement() const;
  // Why the loop has stopped (none while it goes on).
  LoopStop stopped() const { return stopped_; }

  // With nothing awaiting a measurement and the loop not stopped: proposes the next round, writes
  // round-N/round.json and the print's files into round-N/print/, and returns N; or finds the loop
  // done, writes why into the last round and returns nullopt. Throws std::logic_error while a round
  // awaits its measurement.
  std::optional<int> advance();

  // The awaiting round's print as measured: kept in round-N/measurement.json, taken into the model
  // (refit, correction), the model written to round-N/forcing.json and the round's record updated.
  // Throws std::logic_error when no round awaits one, std::invalid_argument for a pairing without
  // friction or vibration or on another surface.
  void take_measurement(const io::Pairing& measured);

  // A rig session of the awaiting round's print, analysed as `catalog build` analyses one: the
  // pairing take_measurement takes. Throws what the analysis throws (naming the session).
  io::Pairing analyse_session(const std::filesystem::path& session) const;

 private:
  LoopSession() = default;
  static std::unique_ptr<LoopSession> open_folder(const std::filesystem::path& folder,
                                                  std::optional<LoopRequest> request,
                                                  std::optional<int> max_rounds,
                                                  const numeric::StepProgress& progress);
  void load(const numeric::StepProgress& progress);
  void take_in(int round, const io::Pairing& measured, bool write);

  std::filesystem::path folder_;
  LoopRequest request_;
  std::vector<LoopRoundRecord> rounds_;
  space::SpaceFile space_;
  std::unique_ptr<PredictionInputs> inputs_;
  forcing::ForcingInputs forcing_inputs_;
  DesignResponseGrid grid_;
  std::optional<io::PrinterProfile> printer_;
  std::unique_ptr<LoopModel> loop_;
  LoopStop stopped_ = LoopStop::none;
};

}  // namespace nibrig::model::design
