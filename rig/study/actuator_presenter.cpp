#include "rig/study/actuator_presenter.hpp"

#include <stdexcept>

namespace nibrig::rig {

std::unique_ptr<rt::StrokeSource> ActuatorPresenter::study_sweep_stroke() {
  return std::make_unique<rt::SweepStroke>();
}

ActuatorPresenter::ActuatorPresenter(playback::LiveAudition& audition,
                                     std::vector<model::design::ToolSound> sounds,
                                     StrokeMaker stroke, std::uint64_t seed)
    : audition_(audition), sounds_(std::move(sounds)), stroke_(std::move(stroke)), seed_(seed) {
  if (audition_.names().size() < 3)
    throw std::invalid_argument("the actuator's audition needs three slots (reference, A, B)");
}

void ActuatorPresenter::prepare(const model::study::PlannedTrial& planned) {
  const std::size_t stimuli[3] = {planned.trial.reference, planned.trial.left, planned.trial.right};
  for (std::size_t slot = 0; slot < 3; ++slot) {
    const model::design::ToolSound& s = sounds_.at(stimuli[slot]);
    // A seed per trial and slot: the forcing noise is not the same sample for sample in every trial.
    audition_.load(slot, s, seed_ + 3 * stimuli[slot] + slot);
  }
}

void ActuatorPresenter::present(model::study::Role role) {
  const std::size_t slot = role == model::study::Role::reference ? 0
                           : role == model::study::Role::left    ? 1
                                                                  : 2;
  audition_.select(slot);
  audition_.attach(stroke_());
}

void ActuatorPresenter::pause() { audition_.set_contact(0.0, 0.0); }

}  // namespace nibrig::rig
