#include "model/study/trial_sequence.hpp"

#include <algorithm>
#include <stdexcept>

#include "model/space/adaptive_plan.hpp"

namespace nibrig::model::study {
namespace {

// The paper's stage 2 repeats each tie ten times and at most 60 of them (Sec. 4.2).
std::size_t paper_stage_one_trials(const space::TwoStageDesign& design, std::size_t triplets) {
  const auto drawn = static_cast<std::size_t>(
      std::llround(design.stage_one_fraction * static_cast<double>(triplets)));
  return std::max<std::size_t>(1, drawn) * static_cast<std::size_t>(design.stage_one_repetitions);
}

std::size_t stage_two_at_most(const space::TwoStageDesign& design, std::size_t stage_one_triplets) {
  const std::size_t cap = design.stage_two_triplets == 0
                              ? stage_one_triplets
                              : std::min(design.stage_two_triplets, stage_one_triplets);
  return cap * static_cast<std::size_t>(design.stage_two_repetitions);
}

// Every pair of candidates against the validation's reference (stimulus 0), in shuffled rounds,
// each pair's sides alternating from round to round and down the round.
std::vector<space::Trial> validation_pairs(std::size_t stimuli, std::size_t budget,
                                           std::mt19937_64& generator) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 1; a < stimuli; ++a)
    for (std::size_t b = a + 1; b < stimuli; ++b) pairs.emplace_back(a, b);
  const std::size_t total = budget == 0 ? pairs.size() : budget;
  std::vector<space::Trial> trials;
  for (std::size_t round = 0; trials.size() < total; ++round) {
    std::vector<std::size_t> order(pairs.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::shuffle(order.begin(), order.end(), generator);
    for (std::size_t k = 0; k < order.size() && trials.size() < total; ++k) {
      const auto [a, b] = pairs[order[k]];
      const bool swap = (order[k] + round) % 2 == 1;
      trials.push_back({0, swap ? b : a, swap ? a : b, 1});
    }
  }
  return trials;
}

// The paper's split for `budget` main trials (space::two_stage_for_budget), cut down where it would
// ask for more: a small budget's one stage-two triplet repeated ten times made "5 main trials" a
// plan of up to 14. Stage 1 keeps its two repetitions while the budget holds two; stage 2 gets
// what is left, as whole repetitions of its ties, fewer repetitions when not even one tie's ten fit.
space::TwoStageDesign two_stage_within_budget(std::size_t stimuli, std::size_t budget) {
  space::TwoStageDesign d = space::two_stage_for_budget(stimuli, budget);
  const std::size_t triplets = space::triplet_count(stimuli);
  std::size_t one = paper_stage_one_trials(d, triplets);
  if (one > budget) {
    if (budget < static_cast<std::size_t>(d.stage_one_repetitions)) d.stage_one_repetitions = 1;
    const std::size_t count = std::max<std::size_t>(1, budget / static_cast<std::size_t>(d.stage_one_repetitions));
    d.stage_one_fraction = static_cast<double>(count) / static_cast<double>(triplets);
    one = paper_stage_one_trials(d, triplets);
  }
  const std::size_t one_triplets = one / static_cast<std::size_t>(d.stage_one_repetitions);
  const std::size_t left = budget - std::min(budget, one);
  const auto reps = static_cast<std::size_t>(d.stage_two_repetitions);
  if (stage_two_at_most(d, one_triplets) > left) {
    if (left >= reps) {
      d.stage_two_triplets = left / reps;
    } else {
      d.stage_two_triplets = 1;
      d.stage_two_repetitions = static_cast<int>(left);  // 0: no stage 2 (TrialSequence skips it)
    }
  }
  return d;
}

}  // namespace

PlanSizes plan_sizes(const StudyDefinition& d) {
  const std::size_t n = d.stimuli.size();
  const std::size_t triplets = space::triplet_count(n);
  PlanSizes sizes;
  sizes.two_stage = d.trials == 0 || d.plan != PlanKind::two_stage
                        ? space::TwoStageDesign{}
                        : two_stage_within_budget(n, d.trials);
  const std::size_t one = paper_stage_one_trials(sizes.two_stage, triplets);
  const std::size_t one_triplets = one / static_cast<std::size_t>(sizes.two_stage.stage_one_repetitions);
  const std::size_t paper_total = one + stage_two_at_most(sizes.two_stage, one_triplets);
  const std::size_t pairs = (n - 1) * (n - 2) / 2;
  switch (d.mode == StudyMode::validation ? PlanKind::file : d.plan) {
    case PlanKind::two_stage: sizes.main_trials_at_most = paper_total; break;
    case PlanKind::adaptive: sizes.main_trials_at_most = d.trials == 0 ? paper_total : d.trials; break;
    case PlanKind::file:
      sizes.main_trials_at_most = d.mode == StudyMode::validation
                                      ? (d.trials == 0 ? pairs : d.trials)
                                      : d.listed_trials.size();
      break;
  }
  // The adaptive start: a fifth of the budget, at least one per stimulus, at most the 100 that
  // the synthetic comparison (`space synth --compare`) started from, and never every triplet.
  sizes.adaptive_initial = std::clamp<std::size_t>(sizes.main_trials_at_most / 5, n, 100);
  sizes.adaptive_initial = std::min({sizes.adaptive_initial, triplets, sizes.main_trials_at_most});
  sizes.adaptive_batch = std::clamp<std::size_t>(sizes.main_trials_at_most / 10, 10, 100);
  return sizes;
}

int last_stage(const StudyDefinition& d) {
  if (d.mode == StudyMode::validation) return 1;
  switch (d.plan) {
    case PlanKind::two_stage: return 2;
    case PlanKind::adaptive: {
      const PlanSizes sizes = plan_sizes(d);
      // Round 1 is the random start; each batch after it is one more round.
      return 1 + static_cast<int>((sizes.main_trials_at_most + sizes.adaptive_batch - 1) /
                                  sizes.adaptive_batch);
    }
    case PlanKind::file: {
      int last = 1;
      for (const auto& t : d.listed_trials) last = std::max(last, t.stage);
      return last;
    }
  }
  return 1;
}

TrialSequence::TrialSequence(StudyDefinition definition, std::uint64_t seed, unsigned threads)
    : definition_(std::move(definition)), generator_(seed) {
  validate(definition_);
  sizes_ = plan_sizes(definition_);
  adaptive_fit_.starts = 4;
  adaptive_fit_.threads = threads;
}

std::size_t TrialSequence::expected_at_most() const noexcept {
  const std::size_t practice =
      std::min(definition_.practice, space::triplet_count(definition_.stimuli.size()));
  if (definition_.mode != StudyMode::validation && definition_.plan == PlanKind::two_stage &&
      stage_two_known_) {
    const std::size_t one = paper_stage_one_trials(
        sizes_.two_stage, space::triplet_count(definition_.stimuli.size()));
    return practice + one + stage_two_size_;
  }
  return practice + sizes_.main_trials_at_most;
}

std::optional<PlannedTrial> TrialSequence::next() {
  while (position_ == queue_.size() && part_ != Part::done) plan_next_part();
  if (position_ == queue_.size()) return std::nullopt;
  return queue_[position_];
}

void TrialSequence::record(space::Choice choice) {
  if (choice == space::Choice::none)
    throw std::invalid_argument("a trial's answer must be left or right");
  if (!next()) throw std::logic_error("no trial waits for an answer: the study is complete");
  answered_.push_back(queue_[position_++]);
  choices_.push_back(choice);
}

void TrialSequence::plan_next_part() {
  const std::size_t n = definition_.stimuli.size();
  const std::size_t triplets = space::triplet_count(n);
  queue_.clear();
  position_ = 0;
  auto enqueue = [this](const std::vector<space::Trial>& trials, bool practice) {
    for (const auto& t : trials) queue_.push_back({t, practice});
  };
  switch (part_) {
    case Part::practice: {
      part_ = Part::main_first;
      const std::size_t count = std::min(definition_.practice, triplets);
      if (count > 0)
        enqueue(space::plan_all_triplets(n, 1, generator_(),
                                         static_cast<double>(count) / static_cast<double>(triplets)),
                true);
      return;
    }
    case Part::main_first: {
      part_ = Part::main_next;
      if (definition_.mode == StudyMode::validation) {
        enqueue(validation_pairs(n, definition_.trials, generator_), false);
        part_ = Part::done;
      } else if (definition_.plan == PlanKind::file) {
        enqueue(definition_.listed_trials, false);
        part_ = Part::done;
      } else if (definition_.plan == PlanKind::two_stage) {
        const auto& d = sizes_.two_stage;
        enqueue(space::plan_all_triplets(n, d.stage_one_repetitions, generator_(),
                                         d.stage_one_fraction),
                false);
      } else {
        enqueue(space::plan_all_triplets(n, 1, generator_(),
                                         static_cast<double>(sizes_.adaptive_initial) /
                                             static_cast<double>(triplets)),
                false);
      }
      return;
    }
    case Part::main_next: {
      if (definition_.plan == PlanKind::two_stage) {
        part_ = Part::done;
        std::vector<space::Trial> one;
        std::vector<space::Choice> answers;
        for (std::size_t i = 0; i < answered_.size(); ++i)
          if (!answered_[i].practice) {
            one.push_back(answered_[i].trial);
            answers.push_back(choices_[i]);
          }
        const auto& d = sizes_.two_stage;
        const auto ties = space::select_ties(space::merge_trials(one, answers), d.ties);
        const auto two = ties.empty() || d.stage_two_repetitions == 0 ? std::vector<space::Trial>{}
                                      : space::plan_stage_two(ties, d.stage_two_repetitions,
                                                              generator_(), d.stage_two_triplets);
        stage_two_size_ = two.size();
        stage_two_known_ = true;
        enqueue(two, false);
        return;
      }
      // Adaptive: the next batch, until the budget is spent.
      std::size_t main = 0;
      for (const auto& t : answered_) main += t.practice ? 0 : 1;
      if (main >= sizes_.main_trials_at_most) {
        part_ = Part::done;
        return;
      }
      enqueue(adaptive_batch(), false);
      if (queue_.empty()) part_ = Part::done;
      return;
    }
    case Part::done: return;
  }
}

std::vector<space::Trial> TrialSequence::adaptive_batch() {
  const std::size_t n = definition_.stimuli.size();
  std::vector<space::Trial> trials;
  std::vector<space::Choice> answers;
  for (std::size_t i = 0; i < answered_.size(); ++i)
    if (!answered_[i].practice) {
      trials.push_back(answered_[i].trial);
      answers.push_back(choices_[i]);
    }
  space::SpaceProblem problem;
  problem.stimuli = n;
  problem.dims = definition_.dims;
  space::LaplaceOptions ensemble;
  problem.prior_sd = ensemble.prior_sd;  // as run_adaptive_study: the posterior the ensemble samples
  problem.triplets = space::merge_trials(trials, answers);
  adaptive_fit_.seed = 1u + 7919u * static_cast<unsigned>(adaptive_round_);
  const space::FitResult fit = space::fit_space(problem, adaptive_fit_);
  adaptive_fit_.initial = fit.coordinates;  // the next round's first start: one batch away
  ++adaptive_round_;
  const std::size_t left = sizes_.main_trials_at_most - trials.size();
  return space::next_adaptive_batch(problem, fit.coordinates, space::all_triplets(n), ensemble,
                                    std::min(sizes_.adaptive_batch, left), adaptive_round_,
                                    generator_);
}

}  // namespace nibrig::model::study
