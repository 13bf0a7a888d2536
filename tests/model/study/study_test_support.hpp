// What the study tests share: a definition over made-up stimuli, the texts a study copies in, and a
// respondent that answers from a script or a simulated space and can stop at a given trial.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "model/study/simulated_participant.hpp"
#include "model/study/study_session.hpp"

namespace nibrig::model::study::test {

inline StudyDefinition definition_of(std::size_t stimuli, PlanKind plan = PlanKind::two_stage) {
  StudyDefinition d;
  for (std::size_t i = 0; i < stimuli; ++i)
    d.stimuli.push_back({"tool" + std::to_string(i) + "/paper", "tool" + std::to_string(i), "paper"});
  d.plan = plan;
  return d;
}

inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

// A study folder made from `d`, with instruction and consent texts.
inline std::filesystem::path make_study(const std::filesystem::path& folder, const StudyDefinition& d) {
  std::filesystem::create_directories(folder);
  write_text(folder.parent_path() / "instructions-src.txt", "Which is closer to the reference?\n");
  write_text(folder.parent_path() / "consent-src.txt", "I agree.\n");
  create_or_join_study(folder / "study", d, folder.parent_path() / "instructions-src.txt",
                       folder.parent_path() / "consent-src.txt");
  return folder / "study";
}

// Answers as a simulated participant does, but stops (Choice::none) at trial `stop_at` (1-based;
// 0: never) and counts rests and what it was asked to play.
class StoppingParticipant final : public Respondent {
 public:
  StoppingParticipant(Eigen::MatrixXd truth, std::uint64_t seed, std::size_t stop_at = 0)
      : inner_(std::move(truth), {}, seed), stop_at_(stop_at) {}
  bool agree(const StudyTexts& texts) override {
    seen_texts = texts;
    return agrees;
  }
  Answer answer(const TrialPrompt& prompt, const std::function<void(Role)>& play) override {
    prompts.push_back(prompt.number);
    if (prompt.number == stop_at_) return {};
    return inner_.answer(prompt, play);
  }
  void rest(std::size_t done, std::size_t) override { rests.push_back(done); }

  bool agrees = true;
  StudyTexts seen_texts;
  std::vector<std::size_t> prompts, rests;

 private:
  SimulatedParticipant inner_;
  std::size_t stop_at_;
};

}  // namespace nibrig::model::study::test
