#include "model/study/simulated_participant.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace nibrig::model::study {
namespace {

// A space of three judged tools that judges by a logistic link with a lapse and a noise each.
space::SpaceFile space_with_lapse_and_noises() {
  space::SpaceFile s;
  s.stimuli = {"a", "b", "c"};
  s.coordinates = Eigen::MatrixXd(1, 3);
  s.coordinates << 0.0, 0.1, 100.0;
  s.model.family = space::parse_family("logistic+lapse+noise");
  s.model.lapse = 0.2;
  s.model.log_noise = Eigen::Vector3d(0.1, 0.2, 0.6);
  return s;
}

TEST(SimulatedParticipantModel, TakesTheSpacesModelWithANoisePerStudyStimulus) {
  const space::SpaceFile space = space_with_lapse_and_noises();
  const std::vector<Stimulus> stimuli = {
      {"c", "t3", "paper"}, {"new", "t9", "paper"}, {"a", "t1", "paper"}};
  const space::JudgmentModel m = judgment_model_for_stimuli(space, stimuli);
  EXPECT_EQ(space::family_name(m.family), "logistic+lapse+noise");
  EXPECT_EQ(m.lapse, 0.2);
  EXPECT_EQ(m.scale, space.model.scale);
  ASSERT_EQ(m.log_noise.size(), 3);
  EXPECT_EQ(m.log_noise(0), 0.6) << "c's own noise";
  EXPECT_NEAR(m.log_noise(1), 0.3, 1e-12) << "a stimulus the space did not judge: the mean noise";
  EXPECT_EQ(m.log_noise(2), 0.1) << "a's own noise";

  space::SpaceFile probit = space;
  probit.model = {};
  EXPECT_EQ(judgment_model_for_stimuli(probit, stimuli).log_noise.size(), 0)
      << "a family without noises keeps none";
}

TEST(SimulatedParticipantModel, AnswersAnObviousTripletAsTheSpacesLapseSays) {
  // Reference a, then b (0.1 away) against c (100 away): the link alone is certain of b, and a
  // lapse ε = 0.2 answers a share ε at random, so the model gives b with probability 1 − ε/2 = 0.9;
  // the paper's probit gives 1.
  const space::SpaceFile space = space_with_lapse_and_noises();
  const std::vector<Stimulus> stimuli = {
      {"a", "t1", "paper"}, {"b", "t2", "paper"}, {"c", "t3", "paper"}};
  SimulatedParticipant by_model(space.coordinates, {}, 9,
                                judgment_model_for_stimuli(space, stimuli));
  SimulatedParticipant by_paper(space.coordinates, {}, 9);
  const std::size_t n = 4000;
  std::size_t model_b = 0, paper_b = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    TrialPrompt prompt;
    prompt.number = k;
    prompt.planned.trial = {0, 1, 2, 1};
    const auto ignore = [](Role) {};
    model_b += by_model.answer(prompt, ignore).choice == space::Choice::left;
    paper_b += by_paper.answer(prompt, ignore).choice == space::Choice::left;
  }
  const double share = static_cast<double>(model_b) / n;
  // Binomial sd at 0.9 over 4000 answers is 0.0047: four of them.
  EXPECT_NEAR(share, 0.9, 0.02);
  EXPECT_EQ(paper_b, n);
  EXPECT_NEAR(by_model.observer().probability_first(0, 1, 2), 0.9, 1e-9);
}

}  // namespace
}  // namespace nibrig::model::study
