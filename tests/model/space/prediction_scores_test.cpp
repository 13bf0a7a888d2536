#include "model/space/prediction_scores.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace nibrig::model::space {
namespace {

io::Triplet triplet(int count_a, int count_b) {
  io::Triplet t;
  t.reference = 0, t.a = 1, t.b = 2;
  t.count_a = count_a, t.count_b = count_b;
  return t;
}

TEST(SpacePredictionScores, CountsMajorityIndividualAgreementAndError) {
  // Three triplets: 7:3 predicted 0.8 (agrees), 2:8 predicted 0.6 (disagrees), 5:5 predicted 0.5.
  const std::vector<io::Triplet> t{triplet(7, 3), triplet(2, 8), triplet(5, 5)};
  const PredictionScores s = score_predictions({0.8, 0.6, 0.5}, t);
  EXPECT_EQ(s.triplets, 3u);
  EXPECT_EQ(s.responses, 30u);
  // The tied triplet has no majority: 1 of 2 decided triplets agree.
  EXPECT_DOUBLE_EQ(s.majority.trials, 2.0);
  EXPECT_DOUBLE_EQ(s.majority.agreements, 1.0);
  // Individually: 7 (first) + 2 (second, the a answers) + 5 (half of the third) = 14 of 30.
  EXPECT_DOUBLE_EQ(s.individual.agreements, 14.0);
  // |0.8−0.7| + |0.6−0.2| + |0.5−0.5| over 3.
  EXPECT_NEAR(s.mean_absolute_error, 0.5 / 3.0, 1e-12);
  ASSERT_TRUE(s.probability_correlation.has_value());
}

TEST(SpacePredictionScores, AnExactHalfIsHalfRightWhicheverSideWon) {
  // With the answer always listed first (Salmon), a tie-break towards the first candidate would
  // score 100 %; a prediction of exactly 0.5 must score 50 %.
  const PredictionScores s = score_predictions({0.5, 0.5}, {triplet(1, 0), triplet(1, 0)});
  EXPECT_DOUBLE_EQ(s.individual.fraction, 0.5);
  EXPECT_DOUBLE_EQ(s.majority.fraction, 0.5);
}

TEST(SpacePredictionScores, RejectsBadInput) {
  EXPECT_THROW(score_predictions({0.5}, {triplet(1, 0), triplet(0, 1)}), std::invalid_argument);
  EXPECT_THROW(score_predictions({1.5}, {triplet(1, 0)}), std::invalid_argument);
  EXPECT_THROW(score_predictions({0.5}, {triplet(0, 0)}), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space
