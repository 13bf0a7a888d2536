// The hold-out summary's per-speed table (what `forcing holdout` prints under "by speed"), on
// three hand-made predictions whose means and wins are counted here by hand.
#include <gtest/gtest.h>

#include "model/design/interpolation_check.hpp"

namespace nibrig::model::design {
namespace {

InterpolatedPrediction prediction(std::vector<double> interpolated, std::vector<double> first,
                                  std::vector<double> second) {
  InterpolatedPrediction p;
  p.tool = "t";
  p.surface = "s";
  p.comparison.interpolated.rms_db_by_speed = std::move(interpolated);
  p.comparison.baselines.resize(2);
  p.comparison.baselines[0].error.rms_db_by_speed = std::move(first);
  p.comparison.baselines[1].error.rms_db_by_speed = std::move(second);
  return p;
}

TEST(HoldOutSummary, MeansAndWinsPerSpeedOverThePredictedToolsOnly) {
  std::vector<InterpolatedPrediction> held{prediction({1.0, 2.0}, {2.0, 1.0}, {3.0, 3.0}),
                                           prediction({2.0, 2.0}, {1.0, 3.0}, {3.0, 4.0}),
                                           prediction({3.0, 0.5}, {4.0, 1.0}, {5.0, 1.0})};
  InterpolatedPrediction skipped;
  skipped.not_predictable = "its surface is in no training exemplar";
  held.push_back(skipped);
  const HoldOutSummary s = summarize(held);
  EXPECT_EQ(s.predicted, 3);
  EXPECT_EQ(s.mean_predicted_db_by_speed, (std::vector<double>{2.0, 1.5}));
  ASSERT_EQ(s.mean_baseline_db_by_speed.size(), 2u);
  EXPECT_DOUBLE_EQ(s.mean_baseline_db_by_speed[0][0], 7.0 / 3);
  EXPECT_DOUBLE_EQ(s.mean_baseline_db_by_speed[0][1], 5.0 / 3);
  EXPECT_DOUBLE_EQ(s.mean_baseline_db_by_speed[1][0], 11.0 / 3);
  EXPECT_DOUBLE_EQ(s.mean_baseline_db_by_speed[1][1], 8.0 / 3);
  // Speed 0: the first and third beat both (1 < 2, 3; 3 < 4, 5), the second loses to 1.0.
  // Speed 1: only the second (2 < 3, 4) and the third (0.5 < 1, 1).
  EXPECT_EQ(s.beats_every_baseline_by_speed, (std::vector<int>{2, 2}));
}

TEST(HoldOutSummary, RefusesPredictionsComparedOverDifferentSpeeds) {
  const std::vector<InterpolatedPrediction> held{prediction({1.0, 2.0}, {2.0, 1.0}, {3.0, 3.0}),
                                                 prediction({1.0}, {2.0}, {3.0})};
  EXPECT_THROW(summarize(held), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::design
