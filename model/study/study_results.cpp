#include "model/study/study_results.hpp"

#include <algorithm>

#include "model/io/format_error.hpp"
#include "model/space/trial_plan.hpp"
#include "model/study/trial_sequence.hpp"

namespace nibrig::model::study {
namespace {

struct MainAnswers {
  std::vector<space::Trial> trials;
  std::vector<space::Choice> choices;
};

MainAnswers main_answers(const ParticipantData& p) {
  MainAnswers m;
  for (const auto& r : p.responses)
    if (!r.practice) {
      m.trials.push_back(r.planned);
      m.choices.push_back(r.chosen);
    }
  return m;
}

// A log with more answers than the study's plan presents was not written by a session of this
// study (one stops when the plan ends): its extra answers would weigh in the fit unnoticed. The
// participant's order is replayed from their seed, as a resumed session does.
void refuse_answers_beyond_the_plan(const std::vector<LoggedResponse>& responses,
                                    const StudyDefinition& definition, std::uint64_t seed,
                                    const std::filesystem::path& file) {
  TrialSequence sequence(definition, seed);
  for (const LoggedResponse& r : responses) {
    if (!sequence.next())
      throw io::FormatError(file, io::line_place(r.trial + 1),
                            "trial " + std::to_string(r.trial) + " is beyond the study's plan, which ends after " +
                                std::to_string(sequence.answered()) +
                                " trials for this participant: this log is not one of this study's sessions");
    sequence.record(r.chosen);
  }
}

}  // namespace

StudyData read_study(const std::filesystem::path& folder) {
  StudyData study;
  study.folder = folder;
  study.definition = read_study_file(folder / kStudyFile);
  std::vector<std::string> names;
  for (const auto& s : study.definition.stimuli) names.push_back(s.name);
  const int last = last_stage(study.definition);
  const std::filesystem::path participants = folder / kParticipantsFolder;
  if (!std::filesystem::is_directory(participants)) return study;
  // Every participant folder on disk is counted, or named in a warning that says why not: a
  // report that drops 40 answers without a word, or merges two people under one ID, misleads.
  std::vector<std::filesystem::path> folders;
  for (const auto& entry : std::filesystem::directory_iterator(participants))
    if (entry.is_directory()) folders.push_back(entry.path());  // beside them: their .lock files
  std::sort(folders.begin(), folders.end());
  const auto not_counted = [&](const std::filesystem::path& f, const std::string& why) {
    study.warnings.push_back(f.string() + ": " + why + "; not counted");
  };
  for (const auto& f : folders) {
    const std::string id = f.filename().string();
    if (!std::filesystem::exists(f / kParticipantFile)) {
      std::string why = std::string("no ") + kParticipantFile + " (whose seed orders the answers)";
      if (std::filesystem::exists(f / kResponsesFile)) {
        std::size_t answers = 0;
        try {
          answers = read_response_file(f / kResponsesFile, names, last).responses.size();
        } catch (const io::FormatError&) {
        }
        why += ", though " + std::string(kResponsesFile) + " holds " + std::to_string(answers) +
               " answers";
      }
      not_counted(f, why);
      continue;
    }
    ParticipantData p;
    p.record = read_participant_file(f / kParticipantFile);
    if (p.record.id != id) {
      not_counted(f, std::string(kParticipantFile) + " names participant '" + p.record.id +
                         "', not the folder's '" + id + "'");
      continue;
    }
    if (std::filesystem::exists(f / kResponsesFile)) {
      ResponseFile file = read_response_file(f / kResponsesFile, names, last);
      refuse_answers_beyond_the_plan(file.responses, study.definition, p.record.seed, f / kResponsesFile);
      p.responses = std::move(file.responses);
      study.warnings.insert(study.warnings.end(), file.warnings.begin(), file.warnings.end());
    }
    study.participants.push_back(std::move(p));
  }
  return study;
}

bool has_main_answers(const ParticipantData& participant) {
  return std::any_of(participant.responses.begin(), participant.responses.end(),
                     [](const LoggedResponse& r) { return !r.practice; });
}

JudgmentSelection default_selection(const StudyDefinition& d) {
  return d.plan == PlanKind::two_stage && d.mode != StudyMode::validation
             ? JudgmentSelection::paper
             : JudgmentSelection::every_answer;
}

io::TripletSet study_judgments(const StudyData& study, JudgmentSelection selection,
                               const std::string& participant) {
  io::TripletSet set;
  for (const auto& s : study.definition.stimuli) set.stimuli.push_back(s.name);
  set.source = study.folder;
  const bool stages = selection == JudgmentSelection::paper &&
                      study.definition.plan == PlanKind::two_stage &&
                      study.definition.mode != StudyMode::validation;
  for (const auto& p : study.participants) {
    if (!participant.empty() && p.record.id != participant) continue;
    const MainAnswers m = main_answers(p);
    std::vector<io::Triplet> counts =
        stages ? space::two_stage_counts(space::merge_trials(m.trials, m.choices, 1),
                                         space::merge_trials(m.trials, m.choices, 2))
               : space::merge_trials(m.trials, m.choices);
    for (auto& t : counts) {
      t.observer = p.record.id;
      set.triplets.push_back(std::move(t));
    }
  }
  return set;
}

std::vector<io::Triplet> pooled_counts(const StudyData& study, const std::string& leave_out) {
  MainAnswers all;
  for (const auto& p : study.participants) {
    if (p.record.id == leave_out) continue;
    const MainAnswers m = main_answers(p);
    all.trials.insert(all.trials.end(), m.trials.begin(), m.trials.end());
    all.choices.insert(all.choices.end(), m.choices.begin(), m.choices.end());
  }
  return space::merge_trials(all.trials, all.choices);
}

}  // namespace nibrig::model::study
