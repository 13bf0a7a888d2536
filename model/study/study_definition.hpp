// A study on disk: the folder every participant of one triplet study shares. `study.json` (format
// "nibrig-study" version 1) holds what makes the trials (stimuli, mode, plan, budget, practice,
// breaks); `instructions.txt` and `consent.txt` beside it are the texts shown before the first
// trial, copied in when the study is made so that an experimenter edits them there.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/space/trial_plan.hpp"
#include "model/study/stimulus_list.hpp"

namespace nibrig::model::study {

// actuator: simulated tools played on the voice-coil actuator; rig: physical tools on the
// turntable; validation: designs judged against a reference tool (Sec. 6.1), the first stimulus.
enum class StudyMode { actuator, rig, validation };
// two_stage: the paper's plan (stage 2 repeats the ties of stage 1); adaptive: batches of highest
// expected information gain; file: a trial list made beforehand (`nibrig space plan`), as listed.
enum class PlanKind { two_stage, adaptive, file };

const char* mode_name(StudyMode mode);  // "actuator", "rig", "validation"
const char* plan_name(PlanKind plan);   // "two-stage", "adaptive", "file"
// nullopt for any other text.
std::optional<StudyMode> parse_mode(const std::string& text);
std::optional<PlanKind> parse_plan(const std::string& text);

struct StudyDefinition {
  std::vector<Stimulus> stimuli;
  StudyMode mode = StudyMode::actuator;
  PlanKind plan = PlanKind::two_stage;
  // plan = file: the trials in their listed order and sides (stage as listed).
  std::vector<space::Trial> listed_trials;
  // Trials of the main part (practice not counted). 0: the plan's own size: two-stage the paper's
  // (half the triplets twice, up to 60 ties ten times), adaptive the same number as two-stage's
  // first stage plus its largest second stage, validation every pair once.
  std::size_t trials = 0;
  std::size_t practice = 3;       // random triplets first, answered but never fitted
  std::size_t break_every = 100;  // a rest after this many trials; 0: none
  std::size_t dims = 2;           // of the adaptive plan's refits and of the report's fit
};

// The texts a participant sees, from the study folder.
struct StudyTexts {
  std::string instructions, consent;
};

inline constexpr const char* kStudyFile = "study.json";
inline constexpr const char* kInstructionsFile = "instructions.txt";
inline constexpr const char* kConsentFile = "consent.txt";

// Throws std::invalid_argument naming the field for a definition no runner can run: fewer than 3
// stimuli, a name twice, dims < 1 or too many for the stimuli, listed trials out of range or with a
// repeated stimulus, a file plan without trials, validation with fewer than 3 stimuli.
void validate(const StudyDefinition& definition);

// Writes study.json atomically (after validate).
void write_study_file(const std::filesystem::path& file, const StudyDefinition& definition);
// Throws io::FormatError naming the file and field.
StudyDefinition read_study_file(const std::filesystem::path& file);

// The first way in which `given` is not the study `existing` (a participant joins a study only
// with the same stimuli, mode and plan): "stimulus 3 is 'a/b' here but 'c/d' in the study";
// nullopt when they are the same study.
std::optional<std::string> study_difference(const StudyDefinition& existing,
                                            const StudyDefinition& given);

// Reads instructions.txt and consent.txt of a study folder (empty text for a missing file).
StudyTexts read_study_texts(const std::filesystem::path& folder);

}  // namespace nibrig::model::study
