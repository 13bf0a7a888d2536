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

void check_session(const SessionSettings& s) {
  check_participant_id(s.participant);
  if (!std::filesystem::exists(s.study / kStudyFile))
    throw std::invalid_argument(s.study.string() + " holds no study (" + kStudyFile + ")");
  const std::filesystem::path folder = participant_folder(s.study, s.participant);
  const bool exists = std::filesystem::exists(folder / kParticipantFile);
  if (exists && !s.resume)
    throw std::invalid_argument("participant " + s.participant + " already has answers in " +
                                s.study.string() +
                                ": continue with --resume, or give a new participant ID");
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

SessionResult run_session(const SessionSettings& s, Presenter& presenter, Respondent& respondent) {
  check_session(s);
  const StudyDefinition definition = read_study_file(s.study / kStudyFile);
  const std::vector<std::string> names = names_of(definition);
  const std::filesystem::path folder = participant_folder(s.study, s.participant);
  const std::filesystem::path responses = folder / kResponsesFile;
  SessionResult result;

  ParticipantRecord record;
  if (s.resume) {
    record = read_participant_file(folder / kParticipantFile);
  } else {
    record = {s.participant, s.seed.value_or(seed_of_participant(s.participant)), s.respondent,
              io::now_utc_iso8601()};
  }
  TrialSequence sequence(definition, record.seed, s.threads);
  if (s.resume && std::filesystem::exists(responses)) {
    ResponseFile logged = read_response_file(responses, names);
    result.warnings = logged.warnings;
    for (const LoggedResponse& r : logged.responses) {
      const auto planned = sequence.next();
      const bool same = planned && planned->practice == r.practice &&
                        planned->trial.reference == r.planned.reference &&
                        planned->trial.left == r.planned.left &&
                        planned->trial.right == r.planned.right &&
                        planned->trial.stage == r.planned.stage;
      if (!same)
        throw io::FormatError(responses, "trial " + std::to_string(r.trial),
                              planned ? "is not the trial the study's plan gives with seed " +
                                            std::to_string(record.seed) +
                                            " (another study, seed or plan?)"
                                      : "lies beyond the end of the study's plan");
      sequence.record(r.chosen);
    }
    result.resumed_at = logged.responses.size();
  }

  const StudyTexts texts = read_study_texts(s.study);
  if (!respondent.agree(texts)) {
    result.declined = true;
    return result;
  }
  std::filesystem::create_directories(folder);
  if (!s.resume) write_participant_file(folder / kParticipantFile, record);
  ResponseLog log(responses, names);
  if (log.removed_cut_off_line() && result.warnings.empty())
    result.warnings.push_back(responses.string() + ": a cut-off last line was removed");

  std::size_t main_done = 0;
  for (const auto& t : sequence.trials()) main_done += t.practice ? 0 : 1;
  while (const auto planned = sequence.next()) {
    presenter.prepare(*planned);
    std::string plays;
    const auto play = [&](Role role) {
      plays.push_back(static_cast<char>(role));
      presenter.present(role);
    };
    TrialPrompt prompt{sequence.answered() + 1, sequence.expected_at_most(), *planned,
                       &definition.stimuli[planned->trial.reference],
                       &definition.stimuli[planned->trial.left],
                       &definition.stimuli[planned->trial.right]};
    const auto start = std::chrono::steady_clock::now();
    const Answer answer = respondent.answer(prompt, play);
    const double measured =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    presenter.pause();
    if (answer.choice == space::Choice::none) return result;  // stopped: this trial is not kept
    LoggedResponse r;
    r.trial = prompt.number;
    r.practice = planned->practice;
    r.planned = planned->trial;
    r.chosen = answer.choice;
    r.response_s = answer.response_s.value_or(measured);
    r.plays = plays;
    r.answered_utc = io::now_utc_iso8601();
    log.append(r);
    sequence.record(answer.choice);
    ++result.answered;
    if (!planned->practice) ++main_done;
    if (!planned->practice && definition.break_every > 0 && main_done % definition.break_every == 0 &&
        sequence.next())
      respondent.rest(sequence.answered(), sequence.expected_at_most());
  }
  result.complete = true;
  return result;
}

}  // namespace nibrig::model::study
