// A study's stimuli on the turntable (the experiment runner's rig mode, as the paper ran Sec. 4.2
// by hand): before a trial the operator is told its three tools; each time the participant asks
// for one, the operator is told what to mount (when it is not mounted already) and the turntable
// runs the study's 3 s sweep over 17-250 mm/s. With the simulated rig the "mounted" tool is the
// stimulus simulated, so the whole flow runs without hardware.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/study/study_session.hpp"
#include "rig/rig.hpp"
#include "rig/speed_profile.hpp"

namespace nibrig::rig {

class TurntablePresenter final : public model::study::Presenter {
 public:
  // The rig with this stimulus mounted: the simulated rig simulates it, the USB rig has whatever
  // the operator mounted.
  using RigOpener = std::function<std::unique_ptr<Rig>(const model::study::Stimulus&)>;
  // Tells the operator what to mount and returns once they have (a terminal waits for Enter, a
  // window for a button); called on the thread that presents.
  using OperatorPrompt = std::function<void(const std::string& message)>;
  // Tells the operator a trial's three tools; must not wait (it is called where the trial is
  // prepared, a window's UI thread among them).
  using OperatorNotice = std::function<void(const std::string& message)>;

  TurntablePresenter(std::vector<model::study::Stimulus> stimuli, RigOpener open,
                     OperatorPrompt mount, OperatorNotice notice = {},
                     SpeedProfile profile = study_sweep_profile(3.0));

  void prepare(const model::study::PlannedTrial& trial) override;
  // Runs the profile once with the stimulus mounted. Throws std::runtime_error naming the rig and
  // why when the run ended early (unplugged, a fault): the session stops there, every answer
  // before it is on disk, and --resume continues with this trial.
  void present(model::study::Role role) override;
  void pause() override {}

  std::size_t runs() const noexcept { return runs_; }
  std::size_t mounts() const noexcept { return mounts_; }

 private:
  std::vector<model::study::Stimulus> stimuli_;
  RigOpener open_;
  OperatorPrompt mount_;
  OperatorNotice notice_;
  SpeedProfile profile_;
  std::optional<model::study::PlannedTrial> trial_;
  std::optional<std::size_t> mounted_;
  std::size_t runs_ = 0, mounts_ = 0;
};

}  // namespace nibrig::rig
