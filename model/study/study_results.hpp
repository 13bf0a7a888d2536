// A study's answers read back: every participant's log, and the judgments a fit reads (the
// triplet CSV of `space fit`), one participant or all merged into one study.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/io/triplets.hpp"
#include "model/study/response_log.hpp"
#include "model/study/study_definition.hpp"

namespace nibrig::model::study {

struct ParticipantData {
  ParticipantRecord record;
  std::vector<LoggedResponse> responses;
};

struct StudyData {
  std::filesystem::path folder;
  StudyDefinition definition;
  std::vector<ParticipantData> participants;  // by ID
  std::vector<std::string> warnings;  // cut-off lines dropped; participants not counted, and why
};

// Throws io::FormatError naming the file that is missing or malformed. A participant folder
// without participant.json, or whose record names another ID, is left out with a warning.
StudyData read_study(const std::filesystem::path& folder);

// False for a participant stopped before the first main trial (practice only, or nothing): the
// report leaves them out of its statistics, with a warning.
bool has_main_answers(const ParticipantData& participant);

// paper: for a two-stage plan, stage 2 and the stage-one triplets that were not ties, per
// participant (Sec. 4.3); every_answer: every main answer. Practice is never included.
enum class JudgmentSelection { paper, every_answer };
// What a study's plan calls for: paper for two-stage, every answer otherwise (the other plans have
// no stages to select between).
JudgmentSelection default_selection(const StudyDefinition& definition);

// The participants' judgments, each triplet's counts with its participant as observer (one
// participant's when `participant` is not empty). Stimuli: the study's, in its order.
io::TripletSet study_judgments(const StudyData& study, JudgmentSelection selection,
                               const std::string& participant = "");

// Every main answer of every participant pooled into counts per triplet (a < b): the majority
// answer of the validation (Sec. 6.1) and the "others" a participant is compared with.
std::vector<io::Triplet> pooled_counts(const StudyData& study,
                                       const std::string& leave_out = "");

}  // namespace nibrig::model::study
