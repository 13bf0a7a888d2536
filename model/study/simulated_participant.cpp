#include "model/study/simulated_participant.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/io/bundled_assets.hpp"
#include "model/space/space_inputs.hpp"

namespace nibrig::model::study {

void validate(const SimulatedParticipantOptions& o) {
  if (!(o.lapse_rate >= 0.0 && o.lapse_rate <= 1.0))
    throw std::invalid_argument("lapse rate must be between 0 and 1, found " +
                                std::to_string(o.lapse_rate));
  if (!(o.non_decision_s >= 0.0) || !(o.median_s > 0.0) || !(o.slowdown >= 0.0) ||
      !(o.log_sd >= 0.0))
    throw std::invalid_argument(
        "a simulated participant's times must be >= 0 (median > 0), and its spread >= 0");
}

SimulatedParticipant::SimulatedParticipant(Eigen::MatrixXd truth,
                                           SimulatedParticipantOptions options, std::uint64_t seed,
                                           space::JudgmentModel model)
    : observer_(std::move(truth), std::move(model)), options_(options), seed_(seed) {
  validate(options_);
}

Answer SimulatedParticipant::answer(const TrialPrompt& prompt,
                                    const std::function<void(Role)>& play) {
  const space::Trial& t = prompt.planned.trial;
  const double p = observer_.probability_first(t.reference, t.left, t.right);
  const double hardness = 1.0 - std::abs(2.0 * p - 1.0);  // 0 obvious, 1 a coin toss
  // Drawn from the seed and the trial's number, not from a running stream: a session stopped and
  // resumed answers each trial as an uninterrupted one would.
  std::seed_seq seeds{static_cast<std::uint32_t>(seed_), static_cast<std::uint32_t>(seed_ >> 32),
                      static_cast<std::uint32_t>(prompt.number)};
  std::mt19937_64 generator(seeds);
  play(Role::reference);
  play(Role::left);
  play(Role::reference);
  play(Role::right);
  std::poisson_distribution<int> extra(2.0 * hardness);
  for (int k = extra(generator); k > 0; --k) {
    play(Role::left);
    play(Role::right);
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const bool lapse = unit(generator) < options_.lapse_rate;
  const bool left = lapse ? unit(generator) < 0.5 : unit(generator) < p;
  std::lognormal_distribution<double> time(
      std::log(options_.median_s * (1.0 + options_.slowdown * hardness)), options_.log_sd);
  return {left ? space::Choice::left : space::Choice::right,
          options_.non_decision_s + time(generator)};
}

Eigen::MatrixXd truth_for_stimuli(const space::SpaceFile& space,
                                  const std::filesystem::path& space_file,
                                  const std::vector<Stimulus>& stimuli,
                                  const std::filesystem::path& catalog_file,
                                  const PlaceOther& other) {
  const std::filesystem::path catalog =
      space.descriptor_map ? io::or_default(catalog_file, io::default_catalog)
                           : std::filesystem::path{};
  space::StimulusLocator locator(space, space_file, catalog);
  Eigen::MatrixXd truth(space.coordinates.rows(), static_cast<Eigen::Index>(stimuli.size()));
  for (std::size_t i = 0; i < stimuli.size(); ++i) {
    const Stimulus& s = stimuli[i];
    const bool judged =
        std::find(space.stimuli.begin(), space.stimuli.end(), s.name) != space.stimuli.end();
    try {
      if (!judged && other)
        if (const auto placed = other(s)) {
          truth.col(static_cast<Eigen::Index>(i)) = *placed;
          continue;
        }
      truth.col(static_cast<Eigen::Index>(i)) =
          locator.locate(judged ? s.name : pairing_of(s), space_file).mean;
    } catch (const std::exception& e) {
      throw std::invalid_argument("the simulated participant cannot place stimulus '" + s.name +
                                  "': " + e.what());
    }
  }
  return truth;
}

space::JudgmentModel judgment_model_for_stimuli(const space::SpaceFile& space,
                                                const std::vector<Stimulus>& stimuli) {
  space::JudgmentModel model = space.model;
  if (space.model.log_noise.size() == 0) return model;
  model.log_noise.setConstant(static_cast<Eigen::Index>(stimuli.size()),
                              space::typical_log_sigma(space.model));
  for (std::size_t i = 0; i < stimuli.size(); ++i) {
    const auto judged = std::find(space.stimuli.begin(), space.stimuli.end(), stimuli[i].name);
    if (judged != space.stimuli.end())
      model.log_noise(static_cast<Eigen::Index>(i)) =
          space.model.log_noise(judged - space.stimuli.begin());
  }
  return model;
}

TrialEstimate estimate_trials(const StudyDefinition& definition, const Eigen::MatrixXd& truth,
                              std::size_t runs, std::uint64_t seed, unsigned threads,
                              const space::JudgmentModel& model) {
  TrialEstimate estimate;
  double sum = 0.0;
  for (std::size_t run = 0; run < runs; ++run) {
    TrialSequence sequence(definition, seed + run, threads);
    SimulatedParticipant participant(truth, {}, seed + run, model);
    const auto ignore = [](Role) {};
    while (const auto planned = sequence.next()) {
      TrialPrompt prompt;
      prompt.number = sequence.answered() + 1;
      prompt.planned = *planned;
      sequence.record(participant.answer(prompt, ignore).choice);
    }
    const std::size_t n = sequence.answered();
    estimate.least = run == 0 ? n : std::min(estimate.least, n);
    estimate.most = std::max(estimate.most, n);
    sum += static_cast<double>(n);
  }
  estimate.runs = runs;
  estimate.mean = runs ? sum / static_cast<double>(runs) : 0.0;
  return estimate;
}

Eigen::MatrixXd estimate_space(std::size_t dims, std::size_t stimuli) {
  std::mt19937_64 generator(1);
  return space::random_space(dims, stimuli, generator);
}

}  // namespace nibrig::model::study
