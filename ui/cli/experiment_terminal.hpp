// A participant at a terminal (`nibrig experiment run` without --simulate), for a machine without
// a screen: keys r, a and b play the reference, A and B as often as wanted, 1 or 2 answers that A
// or B is closer, q stops (--resume continues). On a terminal each key acts at once; from a pipe
// each line is one key, so that a session can be scripted.
#pragma once

#include <cstdio>
#include <string>

#include "model/study/study_session.hpp"

namespace nibrig::ui::cli {

class TerminalParticipant final : public model::study::Respondent {
 public:
  // Reads keys from `in` (a file descriptor), writes prompts to `out`.
  TerminalParticipant(int in, std::FILE* out);
  ~TerminalParticipant() override;
  TerminalParticipant(const TerminalParticipant&) = delete;
  TerminalParticipant& operator=(const TerminalParticipant&) = delete;

  bool agree(const model::study::StudyTexts& texts) override;
  model::study::Answer answer(const model::study::TrialPrompt& prompt,
                              const std::function<void(model::study::Role)>& play) override;
  void rest(std::size_t done, std::size_t expected_at_most) override;

  // Waits for Enter: the rig operator's confirmation that a tool is mounted. False at the end of
  // the input.
  bool wait_for_enter();

 private:
  // The next key; '\n' for Enter (a pipe's empty line), EOF at the end of the input.
  int key();

  int in_;
  std::FILE* out_;
  bool raw_ = false;
  struct Saved;
  Saved* saved_ = nullptr;  // the terminal's settings before raw mode
};

}  // namespace nibrig::ui::cli
