// Starting one participant's session of a triplet study, the same for every face: the participant
// ID and the study definition checked against the folder, unknown stimuli refused, the folder made
// or joined with its texts, the stimuli's sounds made, the presenter chosen (the actuator, the
// turntable or nothing) and the session opened. Here because it joins model/study with the tools'
// sounds (model/design), playback's audition and the rig.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/design/tool_sound.hpp"
#include "model/study/study_session.hpp"
#include "playback/live_audition.hpp"
#include "rig/rig_request.hpp"
#include "rig/study/turntable_presenter.hpp"

namespace nibrig::rig {

// What a face gathers to start a session.
struct StudyStartRequest {
  // The folder, participant, seed, resume, who answers (recorded), the adaptive refits' threads.
  model::study::StudySettings settings;
  // The study as a stimulus list makes it; nullopt: the folder's own (a participant resuming).
  std::optional<model::study::StudyDefinition> definition;
  std::filesystem::path instructions, consent;  // a new study's texts; empty: the bundled ones
  model::design::ToolSoundOptions sounds;       // where the stimuli's sounds come from
  // Actuator and validation modes: the audition (three slots) the sounds play on, asked for once
  // they are made, by ready(). Empty: nothing is presented and no sound is made (a simulated
  // participant answers).
  std::function<playback::LiveAudition&()> audition;
  // Rig mode: the rig every stimulus is swept on (its tool and surface are set per stimulus),
  // asked for once while the request is checked; it may throw to refuse. Empty: rig mode is
  // refused.
  std::function<RigRequest()> rig;
  TurntablePresenter::OperatorPrompt mount;   // rig mode: what to mount, returning once mounted
  TurntablePresenter::OperatorNotice notice;  // rig mode: a trial's three tools; must not wait
};

// Why a session cannot start: which part of the request is at fault (a face names its own option
// or form field for it) and, in what(), what was expected.
class StudyStartRefused : public std::invalid_argument {
 public:
  enum class Field {
    participant,  // the ID: malformed, taken (new), absent (resume), or another seed
    definition,   // no stimulus list for a new study, or one no runner can run
    folder,       // the folder holds another study, or none to resume
    stimulus,     // a stimulus the catalog lacks, or a malformed design point
    rig,          // rig mode with no rig to run it on
  };
  StudyStartRefused(Field field, const std::string& what);
  Field field() const noexcept { return field_; }

 private:
  Field field_;
};

// "participant", "definition", "folder", "stimulus", "rig".
const char* field_name(StudyStartRefused::Field field);

// A session ready for its consent: the presenter is declared first so that the session, which
// holds a reference to it, is destroyed first.
struct ReadyStudy {
  std::unique_ptr<model::study::Presenter> presenter;
  std::unique_ptr<model::study::StudySession> session;
};

// The start in its three steps, for a face that spreads them over its threads (checks at once, the
// sounds on a worker, the presenter where the participant is): construct, prepare(), ready().
// start_study() below is all three in one.
class StudyStart {
 public:
  // Checks everything that can be refused, and writes nothing: the definition against the folder,
  // the participant, the rig (rig mode), every stimulus against the catalog (no meshing). Throws
  // StudyStartRefused; what the study file and catalog readers throw for a broken file.
  explicit StudyStart(StudyStartRequest request);
  StudyStart(StudyStart&&) noexcept;
  StudyStart& operator=(StudyStart&&) noexcept;
  ~StudyStart();

  // The study as the session will run it.
  const model::study::StudyDefinition& definition() const noexcept { return definition_; }
  // The sounds' maker (the catalog read), for what a face does before preparing (a simulated
  // participant places design points with it).
  model::design::ToolSounds& tool_sounds() noexcept { return *tool_sounds_; }

  // Who answers, as the participant's file records it, for a face that knows it only now (a
  // simulated participant judges by the space's model for these stimuli).
  void record_respondent(std::string words) { request_.settings.respondent = std::move(words); }
  // The folder, participant, seed and resume the session will open with.
  const model::study::StudySettings& settings() const noexcept { return request_.settings; }
  // The catalog the stimuli come from (empty: the bundled one).
  const std::filesystem::path& catalog_file() const noexcept { return request_.sounds.catalog; }

  // Makes or joins the study folder, checks the participant against it again, and makes the sound
  // of each stimulus the actuator will play (none in rig mode or with nothing presented; seconds
  // each): progress(done, total) after each, which may throw to cancel. Any thread.
  void prepare(const std::function<void(std::size_t, std::size_t)>& progress = {});
  // After prepare(): the presenter (asking the request for its audition) and the session, on the
  // thread that will present. Throws what the StudySession constructor throws.
  ReadyStudy ready();

 private:
  StudyStartRequest request_;
  model::study::StudyDefinition definition_;
  std::shared_ptr<model::design::ToolSounds> tool_sounds_;  // shared with the turntable's opener
  std::optional<RigRequest> rig_;
  std::vector<model::design::ToolSound> sounds_;
  bool prepared_ = false;
};

// Checks, prepares and readies in one call: a session ready for its consent, or StudyStartRefused
// naming the part of the request at fault.
ReadyStudy start_study(StudyStartRequest request,
                       const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace nibrig::rig
