#include "model/space/two_stage_lists.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <tuple>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::space {
namespace {

std::string trial_row(std::size_t k) { return "trial row " + std::to_string(k + 1); }

// A triplet as the plan draws it: the reference and the unordered pair (sides are balanced).
std::tuple<std::string, std::string, std::string> drawn_triplet(const TrialList& list, const Trial& t) {
  std::string a = list.stimuli[t.left], b = list.stimuli[t.right];
  if (b < a) std::swap(a, b);
  return {list.stimuli[t.reference], a, b};
}

// Each stage-1 triplet of one list presented the same number of times: the plan's repetitions.
void check_repetitions(const TrialList& list, const std::filesystem::path& file) {
  std::map<std::tuple<std::string, std::string, std::string>, std::size_t> seen;
  for (const Trial& t : list.trials)
    if (t.stage == 1) ++seen[drawn_triplet(list, t)];
  if (seen.empty()) return;
  std::map<std::size_t, std::size_t> how_often;  // presentations -> triplets
  for (const auto& [triplet, n] : seen) ++how_often[n];
  if (how_often.size() < 2) return;
  const std::size_t usual =
      std::max_element(how_often.begin(), how_often.end(), [](const auto& x, const auto& y) { return x.second < y.second; })
          ->first;
  // The odd rows are the misspelled one and its triplet's others: name the one with the rarest name.
  std::map<std::size_t, std::size_t> naming;  // stimulus index -> stage-1 trials naming it
  for (const Trial& t : list.trials)
    if (t.stage == 1)
      for (std::size_t i : {t.reference, t.left, t.right}) ++naming[i];
  std::size_t odd = SIZE_MAX, rarest = SIZE_MAX;
  for (std::size_t k = 0; k < list.trials.size(); ++k) {
    const Trial& t = list.trials[k];
    if (t.stage != 1 || seen[drawn_triplet(list, t)] == usual) continue;
    const std::size_t least = std::min({naming[t.reference], naming[t.left], naming[t.right]});
    if (least < rarest) {
      rarest = least;
      odd = k;
    }
  }
  {
    const std::size_t k = odd;
    const Trial& t = list.trials[k];
    const auto& [r, a, b] = drawn_triplet(list, t);
    throw io::FormatError(file, trial_row(k),
                          "the stage-1 triplet " + io::in_quotes(r) + " with " + io::in_quotes(a) + " and " +
                              io::in_quotes(b) + " is presented " + std::to_string(seen[drawn_triplet(list, t)]) +
                              " times, and " + std::to_string(how_often[usual]) + " other triplets " +
                              std::to_string(usual) +
                              " times each: `space plan` presents every stage-1 triplet equally often "
                              "(a misspelled name?)");
  }
}

}  // namespace

TwoStageStimuli stage_one_stimuli(const std::vector<std::filesystem::path>& files, const std::vector<TrialList>& lists) {
  TwoStageStimuli s;
  std::vector<std::size_t> trials_naming;  // per stimulus of s: the distinct stage-1 triplets naming it
  std::map<std::tuple<std::string, std::string, std::string>, bool> counted;
  struct Where {
    std::size_t file, row;
  };
  std::vector<Where> first;
  for (std::size_t f = 0; f < lists.size(); ++f) {
    check_repetitions(lists[f], files[f]);
    for (std::size_t k = 0; k < lists[f].trials.size(); ++k) {
      const Trial& t = lists[f].trials[k];
      if (t.stage != 1) continue;
      const bool repeated = !counted.emplace(drawn_triplet(lists[f], t), true).second;
      for (std::size_t i : {t.reference, t.left, t.right}) {
        const auto [it, added] = s.index.emplace(lists[f].stimuli[i], s.names.size());
        if (added) {
          s.names.push_back(lists[f].stimuli[i]);
          trials_naming.push_back(0);
          first.push_back({f, k});
        }
        if (!repeated) ++trials_naming[it->second];
      }
    }
  }
  if (s.names.empty())
    throw io::FormatError(files.front(), "", "no stage-1 trial: the stimuli of a two-stage experiment are its stage 1's");
  for (std::size_t i = 0; i < s.names.size(); ++i) {
    if (trials_naming[i] != 1) continue;
    std::size_t fewest_other = SIZE_MAX;
    for (std::size_t j = 0; j < s.names.size(); ++j)
      if (j != i) fewest_other = std::min(fewest_other, trials_naming[j]);
    // Three: a plan names each stimulus in at least that many triplets unless it is tiny.
    if (fewest_other == SIZE_MAX || fewest_other < 3) continue;
    throw io::FormatError(files[first[i].file], trial_row(first[i].row),
                          io::in_quotes(s.names[i]) + " is named in this stage-1 triplet only, and every other "
                              "stimulus in " + std::to_string(fewest_other) + " triplets or more: a misspelled name? "
                              "(a stage-1 list names each stimulus in many triplets)");
  }
  return s;
}

void into_stage_one_stimuli(TrialList& list, const std::filesystem::path& file, const TwoStageStimuli& stimuli) {
  for (std::size_t k = 0; k < list.trials.size(); ++k) {
    Trial& t = list.trials[k];
    for (std::size_t* i : {&t.reference, &t.left, &t.right}) {
      const auto it = stimuli.index.find(list.stimuli[*i]);
      if (it == stimuli.index.end())
        throw io::FormatError(file, trial_row(k),
                              "unknown stimulus " + io::in_quotes(list.stimuli[*i]) + " in stage " +
                                  std::to_string(t.stage) + ": no stage-1 trial names it (expected one of the " +
                                  std::to_string(stimuli.names.size()) + " stimuli of stage 1)");
      *i = it->second;
    }
  }
  list.stimuli = stimuli.names;
}

}  // namespace nibrig::model::space
