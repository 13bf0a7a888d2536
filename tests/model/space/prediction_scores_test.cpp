#include "model/space/prediction_scores.hpp"

#include <gtest/gtest.h>

#include <cmath>
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
  // Pearson r of predicted (0.8, 0.6, 0.5) against observed (0.7, 0.2, 0.5), by hand: the
  // deviations' sums are Sxy = 13/300, Sxx = 14/300, Syy = 38/300, so r = 13 / sqrt(14 * 38).
  ASSERT_TRUE(s.probability_correlation.has_value()) << s.no_correlation_because;
  EXPECT_NEAR(s.probability_correlation->r, 13.0 / std::sqrt(14.0 * 38.0), 1e-12);
  EXPECT_EQ(s.probability_correlation->n, 3u);
  EXPECT_TRUE(s.no_correlation_because.empty());
}

TEST(SpacePredictionScores, SaysWhyThereIsNoCorrelation) {
  // One answer per triplet, always for a (as Salmon lists the answer first): every observed
  // probability is 1, so r is undefined, and the scores say so instead of leaving it out silently.
  const PredictionScores s =
      score_predictions({0.9, 0.6, 0.7}, {triplet(1, 0), triplet(1, 0), triplet(1, 0)});
  EXPECT_FALSE(s.probability_correlation.has_value());
  EXPECT_NE(s.no_correlation_because.find("every observed probability is 1"), std::string::npos)
      << s.no_correlation_because;
  const PredictionScores two = score_predictions({0.9, 0.6}, {triplet(1, 0), triplet(0, 1)});
  EXPECT_NE(two.no_correlation_because.find("needs 3"), std::string::npos)
      << two.no_correlation_because;
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
