// The answered trial lists of a two-stage experiment (Sec. 4.2), as `space plan --stage 2` and
// `space merge` read them: the experiment's stimuli are its stage-1 trials', so a name that only a
// stage-2 trial gives (a typo, a list from another study) is refused, not fitted as a stimulus
// judged a handful of times; and a misspelled name inside stage 1 is found by what the plan makes
// of it: a triplet seen once where each of the others was presented the same number of times, or a
// name in one trial where each other name is in many.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "model/space/trial_plan.hpp"

namespace nibrig::model::space {

struct TwoStageStimuli {
  std::vector<std::string> names;  // in the order stage 1 first names them
  std::unordered_map<std::string, std::size_t> index;
};

// The stimuli of the stage-1 trials of `lists` (read from `files`, one each). Throws io::FormatError
// naming the file and trial row: no stage-1 trial at all; in one list, a stage-1 triplet presented
// a different number of times than the others (space plan presents each the same number); a name
// in a single stage-1 trial where every other name is in at least three.
TwoStageStimuli stage_one_stimuli(const std::vector<std::filesystem::path>& files,
                                  const std::vector<TrialList>& lists);

// `list` (read from `file`) renumbered into `stimuli`'s names. Throws io::FormatError naming the
// file, the trial row and the name for a stimulus no stage-1 trial names.
void into_stage_one_stimuli(TrialList& list, const std::filesystem::path& file, const TwoStageStimuli& stimuli);

}  // namespace nibrig::model::space
