#include "rig/study/turntable_presenter.hpp"

#include <stdexcept>

namespace nibrig::rig {
namespace {

const char* role_words(model::study::Role role) {
  switch (role) {
    case model::study::Role::reference: return "the reference";
    case model::study::Role::left: return "A";
    case model::study::Role::right: return "B";
  }
  return "?";
}

}  // namespace

TurntablePresenter::TurntablePresenter(std::vector<model::study::Stimulus> stimuli, RigOpener open,
                                       OperatorPrompt mount, OperatorNotice notice,
                                       SpeedProfile profile)
    : stimuli_(std::move(stimuli)),
      open_(std::move(open)),
      mount_(std::move(mount)),
      notice_(std::move(notice)),
      profile_(std::move(profile)) {}

void TurntablePresenter::prepare(const model::study::PlannedTrial& planned) {
  trial_ = planned;
  const auto& t = planned.trial;
  if (!notice_) return;
  notice_("trial with reference " + model::study::pairing_of(stimuli_[t.reference]) + ", A " +
        model::study::pairing_of(stimuli_[t.left]) + ", B " +
        model::study::pairing_of(stimuli_[t.right]) + ": have them at hand");
}

void TurntablePresenter::present(model::study::Role role) {
  if (!trial_) throw std::logic_error("present before prepare");
  const auto& t = trial_->trial;
  const std::size_t index = role == model::study::Role::reference ? t.reference
                            : role == model::study::Role::left    ? t.left
                                                                   : t.right;
  const model::study::Stimulus& s = stimuli_[index];
  if (mounted_ != index) {
    mount_("mount " + s.tool + " on " + s.surface + " (" + role_words(role) + ")");
    mounted_ = index;
    ++mounts_;
  }
  std::unique_ptr<Rig> rig = open_(s);
  rig->start(profile_);
  RigData data;
  while (rig->read(data, std::chrono::milliseconds(100))) data.clear();
  ++runs_;
  const RigHealth health = rig->health();
  if (!health.connected || health.ended_because != "profile finished")
    throw std::runtime_error(rig->description().name + ": the sweep ended early (" +
                             health.ended_because + ")");
}

}  // namespace nibrig::rig
