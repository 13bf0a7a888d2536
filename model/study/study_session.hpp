// One participant's session of a study, the same for every face (a terminal, a window, a
// simulated participant): the trials in their order, each stimulus played when
// the participant asks for it, each answer appended to disk the moment it is given, rests every N
// trials, and a session killed at any point continued where it stopped. Where the stimuli come
// from (the actuator, the rig, nothing) and who answers are the two interfaces below.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/study/participant_lock.hpp"
#include "model/study/response_log.hpp"
#include "model/study/study_definition.hpp"
#include "model/study/trial_sequence.hpp"

namespace nibrig::model::study {

// Which of a trial's three stimuli; the letter is how responses.csv records the plays.
enum class Role : char { reference = 'R', left = 'A', right = 'B' };

// What makes a trial's stimuli felt: the actuator (playback), the turntable (rig), or nothing (a
// simulated participant). Called on the session's thread.
class Presenter {
 public:
  virtual ~Presenter() = default;
  // Gets the trial's three stimuli ready (load their sounds, tell the operator what to mount).
  virtual void prepare(const PlannedTrial& trial) = 0;
  // Plays one of them now, instead of whatever played before.
  virtual void present(Role role) = 0;
  // Silence: between trials, for a rest, at the end.
  virtual void pause() = 0;
};

class NothingPresented final : public Presenter {
 public:
  void prepare(const PlannedTrial&) override {}
  void present(Role) override {}
  void pause() override {}
};

struct TrialPrompt {
  std::size_t number = 0;            // 1-based, practice included
  std::size_t expected_at_most = 0;  // the same count
  PlannedTrial planned;
  const Stimulus* reference = nullptr;
  const Stimulus* left = nullptr;
  const Stimulus* right = nullptr;
};

// Choice::none: the participant stopped; the trial is not recorded and the session ends (resume
// continues with it). response_s: when the respondent knows it (a simulated one); otherwise the
// session measures from the trial's start to the answer.
struct Answer {
  space::Choice choice = space::Choice::none;
  std::optional<double> response_s;
};

// Who answers: a person at a terminal or in a window, or a simulated participant.
class Respondent {
 public:
  virtual ~Respondent() = default;
  // Shown once before the first trial of a session (a resumed one too). False: the participant
  // declined; nothing is recorded.
  virtual bool agree(const StudyTexts& texts) = 0;
  // `play(role)` presents that stimulus; call it as often as the participant asks.
  virtual Answer answer(const TrialPrompt& prompt, const std::function<void(Role)>& play) = 0;
  // A rest after `done` trials, before the next.
  virtual void rest(std::size_t done, std::size_t expected_at_most) = 0;
};

// Makes the study folder with `definition` (and instructions and consent copied from the given
// files), or checks that the folder's study is the same one. Throws std::invalid_argument naming
// the difference (a participant joins a study only with the same stimuli, mode and plan) and what
// validate and the file readers throw; a missing text file is an io::FormatError naming it.
StudyDefinition create_or_join_study(const std::filesystem::path& folder,
                                     const StudyDefinition& definition,
                                     const std::filesystem::path& instructions,
                                     const std::filesystem::path& consent);

struct StudySettings {
  std::filesystem::path study;  // the folder
  std::string participant;
  std::optional<std::uint64_t> seed;  // new participant: default seed_of_participant; resume: must match
  bool resume = false;
  std::string respondent = "a person";  // recorded in participant.json
  unsigned threads = 0;                 // the adaptive plan's refits
  // How the face asks to resume, named where a taken ID is refused: an option, a checkbox.
  std::string resume_named = "--resume";
};

// The participant's folder (study/participants/ID).
std::filesystem::path participant_folder(const std::filesystem::path& study, const std::string& id);

// Checks, before anyone starts, that the session can run: the study exists; a new participant's
// ID is not taken (else "asks for --resume or a new ID"); a resumed one exists and its seed is the
// one given. Throws std::invalid_argument saying which.
void check_study_settings(const StudySettings& settings);

struct StudyResult {
  std::size_t resumed_at = 0;   // trials answered before this session
  std::size_t answered = 0;     // in this session
  bool complete = false;        // every trial of the plan answered
  bool declined = false;        // the consent was declined
  std::vector<std::string> warnings;  // a cut-off line dropped, ...
};

// One participant's session step by step, for a face that drives it from its own loop (a
// window's frames): constructed, it has checked the session and replayed a resumed log; begin()
// after the consent; then for each trial current(), play() as often as asked, answer(). Each answer
// is on disk before answer() returns and the next trial is prepared (its stimuli loaded through the
// presenter). Throws what check_study_settings throws; on resume io::FormatError naming the
// responses file and the trial where a logged trial is not the one the plan gives (another study
// or seed).
class StudySession {
 public:
  StudySession(const StudySettings& settings, Presenter& presenter);
  ~StudySession();
  StudySession(const StudySession&) = delete;
  StudySession& operator=(const StudySession&) = delete;

  const StudyDefinition& definition() const noexcept { return definition_; }
  const StudyTexts& texts() const noexcept { return texts_; }
  // Writes the participant's file (a new one), opens the log, prepares the first trial.
  void begin();
  bool begun() const noexcept { return log_ != nullptr; }
  // The trial waiting for its answer; nullopt once the plan is complete (or before begin()).
  std::optional<TrialPrompt> current() const;
  // Presents one of the current trial's stimuli (recorded in its plays).
  void play(Role role);
  // Records the answer to the current trial; response_s: measured from the trial's start when not
  // given. Returns true when a rest is due before the next trial.
  bool answer(space::Choice choice, std::optional<double> response_s = std::nullopt);
  // The current trial's plays so far ("RAB").
  const std::string& plays() const noexcept { return plays_; }
  bool complete() const;
  const StudyResult& result() const noexcept { return result_; }
  // Silences the presenter: the participant stopped.
  void pause();

 private:
  void prepare_current();

  StudySettings settings_;
  Presenter& presenter_;
  std::unique_ptr<ParticipantLock> lock_;  // held for the session's whole life
  StudyDefinition definition_;
  std::vector<std::string> names_;
  StudyTexts texts_;
  ParticipantRecord record_;
  std::unique_ptr<TrialSequence> sequence_;
  std::unique_ptr<ResponseLog> log_;
  StudyResult result_;
  std::size_t main_done_ = 0;
  std::string plays_;
  std::chrono::steady_clock::time_point trial_start_;
};

// Runs (or resumes) one participant until the plan is complete or the respondent stops: a
// StudySession driven by a Respondent. Throws as StudySession.
StudyResult run_study(const StudySettings& settings, Presenter& presenter, Respondent& respondent);
// The same with a session already open (by rig::start_study, say), not yet begun.
StudyResult run_study(StudySession& session, Respondent& respondent);

}  // namespace nibrig::model::study
