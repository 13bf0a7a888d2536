// `nibrig experiment report`'s work, for every face: a study's judgments merged and written as the
// CSV `space fit` reads, the space fitted to them (with the catalog's descriptors when every
// stimulus is a catalog pairing) and its bootstrap regions, how well each participant agrees with
// the space and with the others, and for a validation study the statistics of Sec. 6.1 against a
// given space (majority agreement and its z-test against chance, individual agreement, error and
// correlation of the predicted preference).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/numeric/cancellation.hpp"
#include "model/space/prediction_scores.hpp"
#include "model/space/space_fit_file.hpp"
#include "model/study/study_results.hpp"

namespace nibrig::model::study {

struct StudyReportSettings {
  std::optional<JudgmentSelection> selection;  // default_selection when not given
  int starts = 16;
  int bootstrap = 200;  // resamples; 0: no regions
  unsigned seed = 1;
  unsigned threads = 0;
  std::filesystem::path catalog;  // of the descriptors and placements; empty: the bundled one
  // The space a validation study is scored against (required for one, refused for another).
  std::filesystem::path validation_space;
  space::StepProgress progress;
  std::stop_token stop;
};

struct ParticipantSummary {
  std::string id, respondent;
  std::size_t answers = 0, practice = 0;  // main answers, practice answers
  double median_response_s = 0.0;         // of the main answers
  // Each main answer scored against the space's prediction (the fitted space, or for a
  // validation study the given one).
  space::AgreementTest with_space;
  // Each main answer against the majority of the other participants on the same triplet (ties in
  // that majority count half); none when no other participant judged any of its triplets.
  std::optional<space::AgreementTest> with_others;
};

struct StudyReport {
  StudyData study;
  JudgmentSelection selection = JudgmentSelection::paper;
  io::TripletSet judgments;
  std::optional<space::FittedSpace> fitted;  // not for a validation study
  bool with_descriptors = false;
  std::vector<ParticipantSummary> participants;
  // Validation: every triplet's pooled counts, the space's P(a chosen), and their scores.
  std::vector<io::Triplet> validation_triplets;
  std::vector<double> validation_predicted;
  std::optional<space::PredictionScores> validation;
  std::filesystem::path validation_space;
  std::vector<std::string> warnings;
};

inline constexpr const char* kReportJudgments = "judgments.csv";
inline constexpr const char* kReportSpace = "space.json";
inline constexpr const char* kReportStatistics = "report.json";

// Reads the study in `study_folder`, writes judgments.csv, space.json (not for a validation study)
// and report.json into `report_folder` (created), and returns what it wrote. Throws
// std::invalid_argument for a study without answers, a validation study without a space or another
// study with one, and what read_study, fit_space_file and bootstrap_space throw
// (numeric::Cancelled when cancelled). The space is read before anything is written.
StudyReport report_study(const std::filesystem::path& study_folder,
                         const std::filesystem::path& report_folder,
                         const StudyReportSettings& settings = {});

}  // namespace nibrig::model::study
