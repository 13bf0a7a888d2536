// A study's stimuli felt on the voice-coil actuator (the experiment runner's actuator mode): each
// stimulus's sound is made once before anyone starts (a catalog tool through the stylus's modes, a
// design point predicted: seconds each), a trial loads its three into the audition's three slots,
// and each time the participant asks for one it plays from the start of the stroke. Here rather
// than in playback/ because it joins a study (model/study) with the tools' sounds (model/design).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "model/design/tool_sound.hpp"
#include "model/study/study_session.hpp"
#include "playback/live_audition.hpp"
#include "rt/stroke_source.hpp"

namespace nibrig::rig {

class ActuatorPresenter final : public model::study::Presenter {
 public:
  using StrokeMaker = std::function<std::unique_ptr<rt::StrokeSource>()>;
  // The study's stroke (Sec. 8): 17 → 250 → 17 mm/s over 3 s at 2.2 N, repeated while it plays.
  static std::unique_ptr<rt::StrokeSource> study_sweep_stroke();

  // `audition` needs three slots. sounds: one per stimulus of the study, in its order.
  ActuatorPresenter(playback::LiveAudition& audition, std::vector<model::design::ToolSound> sounds,
                    StrokeMaker stroke = study_sweep_stroke, std::uint64_t seed = 1);

  void prepare(const model::study::PlannedTrial& trial) override;
  void present(model::study::Role role) override;
  void pause() override;

 private:
  playback::LiveAudition& audition_;
  std::vector<model::design::ToolSound> sounds_;
  StrokeMaker stroke_;
  std::uint64_t seed_;
};

}  // namespace nibrig::rig
