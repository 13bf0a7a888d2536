#include "model/study/study_session.hpp"

#include <chrono>
#include <stdexcept>
#include <system_error>

#include "model/io/format_error.hpp"
#include "model/io/utc_time.hpp"

namespace nibrig::model::study {
namespace {

void copy_text(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (!std::filesystem::is_regular_file(from))
    throw io::FormatError(from, "", "expected a text file to copy into the study");
  std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
}

std::vector<std::string> names_of(const StudyDefinition& d) {
  std::vector<std::string> names;
  for (const auto& s : d.stimuli) names.push_back(s.name);
  return names;
}

}  // namespace

StudyDefinition create_or_join_study(const std::filesystem::path& folder,
                                     const StudyDefinition& definition,
                                     const std::filesystem::path& instructions,
                                     const std::filesystem::path& consent) {
  validate(definition);
  const std::filesystem::path file = folder / kStudyFile;
  if (std::filesystem::exists(file)) {
    StudyDefinition existing = read_study_file(file);
    if (const auto difference = study_difference(existing, definition))
      throw std::invalid_argument(folder.string() + " holds another study: " + *difference +
                                  "; use another folder for a new study");
    return existing;
  }
  std::filesystem::create_directories(folder / kParticipantsFolder);
  copy_text(instructions, folder / kInstructionsFile);
  copy_text(consent, folder / kConsentFile);
  write_study_file(file, definition);
  return definition;
}

std::filesystem::path participant_folder(const std::filesystem::path& study, const std::string& id) {
  return study / kParticipantsFolder / id;
}

void check_study_settings(const StudySettings& s) {
  check_participant_id(s.participant);
  if (!std::filesystem::exists(s.study / kStudyFile))
    throw std::invalid_argument(s.study.string() + " holds no study (" + kStudyFile + ")");
  const std::filesystem::path folder = participant_folder(s.study, s.participant);
  const bool exists = std::filesystem::exists(folder / kParticipantFile);
  if (exists && !s.resume)
    throw std::invalid_argument("participant " + s.participant + " already has answers in " +
                                s.study.string() +
                                ": continue with " + s.resume_named + ", or give a new participant ID");
  if (!exists && s.resume)
    throw std::invalid_argument("participant " + s.participant + " has no session in " +
                                s.study.string() + " to resume");
  if (exists && s.seed) {
    const ParticipantRecord record = read_participant_file(folder / kParticipantFile);
    if (record.seed != *s.seed)
      throw std::invalid_argument("participant " + s.participant + " started with seed " +
                                  std::to_string(record.seed) + ", not " +
                                  std::to_string(*s.seed) +
                                  ": a resumed session keeps its seed (leave --seed out)");
  }
}

StudySession::StudySession(const StudySettings& settings, Presenter& presenter)
    : settings_(settings), presenter_(presenter) {
  // A clear refusal first, when there is no study or the ID is taken.
  check_study_settings(settings_);
  lock_ = std::make_unique<ParticipantLock>(settings_.study, settings_.participant);
  check_study_settings(settings_);  // again, now that no other session can change the participant
  definition_ = read_study_file(settings_.study / kStudyFile);
  names_ = names_of(definition_);
  const std::filesystem::path folder = participant_folder(settings_.study, settings_.participant);
  const std::filesystem::path responses = folder / kResponsesFile;
  if (settings_.resume)
    record_ = read_participant_file(folder / kParticipantFile);
  else
    record_ = {settings_.participant, settings_.seed.value_or(seed_of_participant(settings_.participant)),
               settings_.respondent, io::now_utc_iso8601()};
  sequence_ = std::make_unique<TrialSequence>(definition_, record_.seed, settings_.threads);
  if (settings_.resume && std::filesystem::exists(responses)) {
    ResponseFile logged = read_response_file(responses, names_, last_stage(definition_));
    result_.warnings = logged.warnings;
    for (const LoggedResponse& r : logged.responses) {
      const auto planned = sequence_->next();
      const bool same = planned && planned->practice == r.practice &&
                        planned->trial.reference == r.planned.reference &&
                        planned->trial.left == r.planned.left &&
                        planned->trial.right == r.planned.right &&
                        planned->trial.stage == r.planned.stage;
      if (!same)
        throw io::FormatError(responses, "trial " + std::to_string(r.trial),
                              planned ? "is not the trial the study's plan gives with seed " +
                                            std::to_string(record_.seed) +
                                            " (another study, seed or plan?)"
                                      : "lies beyond the end of the study's plan");
      sequence_->record(r.chosen);
      if (!r.practice) ++main_done_;
    }
    result_.resumed_at = logged.responses.size();
  }
  texts_ = read_study_texts(settings_.study);
}

StudySession::~StudySession() = default;

void StudySession::begin() {
  if (log_) return;
  const std::filesystem::path folder = participant_folder(settings_.study, settings_.participant);
  std::filesystem::create_directories(folder);
  if (!settings_.resume) write_participant_file(folder / kParticipantFile, record_);
  log_ = std::make_unique<ResponseLog>(folder / kResponsesFile, names_);
  if (log_->removed_cut_off_line() && result_.warnings.empty())
    result_.warnings.push_back((folder / kResponsesFile).string() + ": a cut-off last line was removed");
  prepare_current();
}

void StudySession::prepare_current() {
  plays_.clear();
  result_.complete = !sequence_->next().has_value();
  if (!result_.complete) presenter_.prepare(*sequence_->next());
  trial_start_ = std::chrono::steady_clock::now();
}

std::optional<TrialPrompt> StudySession::current() const {
  if (!log_) return std::nullopt;
  const auto planned = sequence_->next();
  if (!planned) return std::nullopt;
  return TrialPrompt{sequence_->answered() + 1, sequence_->expected_at_most(), *planned,
                     &definition_.stimuli[planned->trial.reference],
                     &definition_.stimuli[planned->trial.left],
                     &definition_.stimuli[planned->trial.right]};
}

void StudySession::play(Role role) {
  if (!current()) throw std::logic_error("no trial to play: the session has not begun or is complete");
  plays_.push_back(static_cast<char>(role));
  presenter_.present(role);
}

bool StudySession::answer(space::Choice choice, std::optional<double> response_s) {
  const auto prompt = current();
  if (!prompt) throw std::logic_error("no trial waits for an answer");
  if (choice == space::Choice::none) throw std::invalid_argument("an answer is left or right");
  const double measured =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - trial_start_).count();
  presenter_.pause();
  LoggedResponse r;
  r.trial = prompt->number;
  r.practice = prompt->planned.practice;
  r.planned = prompt->planned.trial;
  r.chosen = choice;
  r.response_s = response_s.value_or(measured);
  r.plays = plays_;
  r.answered_utc = io::now_utc_iso8601();
  log_->append(r);
  sequence_->record(choice);
  ++result_.answered;
  if (!r.practice) ++main_done_;
  prepare_current();
  return !r.practice && definition_.break_every > 0 && main_done_ % definition_.break_every == 0 &&
         !result_.complete;
}

bool StudySession::complete() const { return result_.complete; }

void StudySession::pause() { presenter_.pause(); }

StudyResult run_study(const StudySettings& settings, Presenter& presenter, Respondent& respondent) {
  StudySession session(settings, presenter);
  return run_study(session, respondent);
}

StudyResult run_study(StudySession& session, Respondent& respondent) {
  if (!respondent.agree(session.texts())) {
    StudyResult declined = session.result();
    declined.declined = true;
    return declined;
  }
  session.begin();
  while (const auto prompt = session.current()) {
    const Answer a = respondent.answer(*prompt, [&session](Role role) { session.play(role); });
    if (a.choice == space::Choice::none) {
      session.pause();
      return session.result();  // stopped: this trial is not kept
    }
    if (session.answer(a.choice, a.response_s))
      respondent.rest(session.result().resumed_at + session.result().answered,
                      session.current() ? session.current()->expected_at_most : 0);
  }
  return session.result();
}

}  // namespace nibrig::model::study
