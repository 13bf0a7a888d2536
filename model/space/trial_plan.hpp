// Experiment design for triplet judgments (Sec. 4.2-4.3): the trial lists of the paper's two-stage
// procedure (stage 1: every triplet a few times; stage 2: the ties many times), the merge of
// answers into counts for the fit, and the trial-list CSV an experimenter runs and feeds back.
#pragma once

#include <cstddef>
#include <cstdint>
#include <climits>
#include <filesystem>
#include <string>
#include <vector>

#include "model/io/triplets.hpp"

namespace nibrig::model::space {

// One presentation: which candidate is shown (or handed over) first/left is a nuisance the plan
// balances, so that a side bias of the observer cancels out.
struct Trial {
  std::size_t reference = 0, left = 0, right = 0;
  int stage = 1;
};

// The answer to a trial; none: not answered yet (a list handed out but not finished).
enum class Choice : std::uint8_t { none, left, right };

// n·C(n−1, 2): reference r and an unordered candidate pair {a, b} not containing r (1365 for 15).
std::size_t triplet_count(std::size_t stimuli);

// Every triplet once, as (reference, a < b) with zero counts, ordered by reference, a, b.
std::vector<io::Triplet> all_triplets(std::size_t stimuli);

// Stage 1: round(fraction · triplet_count) triplets drawn at random (fraction 1: all of them; the
// paper presented half, twice each), each `repetitions` times, in random order. Left/right balance:
// each triplet shows each candidate on the left ⌊repetitions/2⌋ times; with an odd count the extra
// presentations are oriented (along Euler paths of the multigraph of candidate pairs) so that over
// the whole list every stimulus is on the left as often as on the right, ±1. Deterministic in seed.
// Throws std::invalid_argument for stimuli < 3, repetitions < 1 or fraction outside (0, 1].
std::vector<Trial> plan_all_triplets(std::size_t stimuli, int repetitions, std::uint64_t seed,
                                     double fraction = 1.0);

// Counts per triplet from answered trials: (reference, a < b) with count_a = how often a was
// chosen, ordered by reference, a, b; only trials of `stage` (0: every stage). An unanswered trial
// (Choice::none) carries no judgment and is skipped; a triplet with no answered trial is not
// listed. Throws std::invalid_argument when choices and trials differ in length.
std::vector<io::Triplet> merge_trials(const std::vector<Trial>& trials,
                                      const std::vector<Choice>& choices, int stage = 0);

// A triplet "resulted in a tie" (Sec. 4.3) when |count_a − count_b| <= max_difference. The default
// 1 means "as even as the number of judgments allows": with the paper's two judgments only 1-1 is a
// tie (the difference of two answers is even), with three 2-1 is; a single judgment is always a tie
// (one answer cannot show that the outcome is obvious). Triplets without judgments are never ties.
struct TieRule {
  int max_difference = 1;
};

bool is_tie(const io::Triplet& counts, const TieRule& rule = {});

// The ties among stage-one counts, in their order.
std::vector<io::Triplet> select_ties(const std::vector<io::Triplet>& stage_one,
                                     const TieRule& rule = {});

// Stage 2: each tie `repetitions` times (left/right balanced as above), random order, stage = 2.
// When max_triplets > 0 and there are more ties, that many are drawn at random (the paper took 60;
// it does not say how it chose among more). Throws std::invalid_argument for repetitions < 1.
std::vector<Trial> plan_stage_two(const std::vector<io::Triplet>& ties, int repetitions = 10,
                                  std::uint64_t seed = 1, std::size_t max_triplets = 0);

// The paper's data for the fit: "all the triplets from the second stage and those that did not
// result in a tie in the first stage". Stage-one counts of a triplet that stage 2 repeated are not
// added to it; ties that stage 2 did not repeat are dropped (as the paper says; note this keeps
// the clear stage-one outcomes and drops the even ones, which biases distances upward).
std::vector<io::Triplet> two_stage_counts(const std::vector<io::Triplet>& stage_one,
                                          const std::vector<io::Triplet>& stage_two,
                                          const TieRule& rule = {});

// A trial list as a file: header `trial,stage,reference,left,right[,chosen]`, stimulus names in
// the name columns, trial numbered from 1, chosen = left | right | empty (not answered yet).
struct TrialList {
  std::vector<std::string> stimuli;
  std::vector<Trial> trials;
  std::vector<Choice> choices;  // one per trial (Choice::none when unanswered)
};

// Writes through a temporary file and a rename (always with the chosen column). Throws
// io::FormatError naming the file and trial for an index out of range, a repeated stimulus in a
// trial, a name the format cannot hold, or choices not matching trials (empty choices: none yet).
void write_trial_csv(const std::filesystem::path& file, const TrialList& list);

// Reads a trial list. With `stimuli` given, names must be among them and keep their indices (so
// that answers line up with the plan and the fit); otherwise stimuli are numbered in order of first
// appearance. Throws io::FormatError naming the file, line and field and what was expected: missing
// column, a trial number not a positive whole number or repeated, a stage < 1, an empty or unknown
// name, the same stimulus twice in a trial, chosen other than left/right/empty.
// `last_stage` bounds the stage column: kTwoStageLast for the paper's two-stage lists (space plan,
// space merge), whose stage 3 would be silently left out of every count.
inline constexpr int kTwoStageLast = 2;
TrialList read_trial_csv(const std::filesystem::path& file,
                         const std::vector<std::string>& stimuli = {}, int last_stage = INT_MAX);

}  // namespace nibrig::model::space
