// The no-interpolation baseline (Fig. 14's grey lines) on the hand-made model: which fitted designs
// stand beside a point, and that the comparison ranks a measurement made of the interpolated
// prediction, or of a corner's, the way it must.
#include "model/design/no_interpolation_baseline.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "model/design/predicted_tool.hpp"
#include "tests/model/design/hand_made_forcing_model.hpp"

namespace nibrig::model::design {
namespace {

using ::testing::HasSubstr;

std::vector<std::string> corner_names(const std::vector<DesignPoint>& corners) {
  std::vector<std::string> names;
  for (const auto& c : corners) names.push_back(to_string(c));
  return names;
}

TEST(NoInterpolationCorners, AreEveryMaterialOfTheMixAtTheFittedTipsAroundTheTip) {
  const auto model = hand_made_model();
  // Between the fitted 2 and 4 mm tips: each material at each.
  EXPECT_THAT(corner_names(
                  no_interpolation_corners(model, parse_design_point("DM85:0.5,vero:0.5,tip=3mm"))),
              ::testing::ElementsAre(to_string(parse_design_point("DM85,tip=2mm")),
                                     to_string(parse_design_point("DM85,tip=4mm")),
                                     to_string(parse_design_point("vero,tip=2mm")),
                                     to_string(parse_design_point("vero,tip=4mm"))));
  // A fitted tip with a mix: only the materials are interpolated.
  EXPECT_THAT(corner_names(no_interpolation_corners(
                  model, parse_design_point("DM85:0.25,vero:0.75,tip=1mm"))),
              ::testing::ElementsAre(to_string(parse_design_point("DM85,tip=1mm")),
                                     to_string(parse_design_point("vero,tip=1mm"))));
  // One material between tips: only the tip is.
  EXPECT_THAT(corner_names(no_interpolation_corners(model, parse_design_point("DM95,tip=1.5mm"))),
              ::testing::ElementsAre(to_string(parse_design_point("DM95,tip=1mm")),
                                     to_string(parse_design_point("DM95,tip=2mm"))));
  // A fitted design has nothing interpolated, so no baseline.
  EXPECT_TRUE(no_interpolation_corners(model, parse_design_point("vero,tip=4mm")).empty());
}

TEST(NoInterpolationCorners, RefuseWhatCannotBePredicted) {
  const auto model = hand_made_model();
  try {
    no_interpolation_corners(model, parse_design_point("vero,tip=5mm"));
    FAIL() << "a 5 mm tip lies outside the fitted 1-4 mm";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("1 mm above the largest"));
  }
  EXPECT_THROW(no_interpolation_corners(model, parse_design_point("teflon,tip=2mm")),
               std::invalid_argument);
}

TEST(CompareWithBaselines, AMeasurementThatIsTheInterpolationBeatsEveryBaseline) {
  const auto model = hand_made_model();
  const auto point = parse_design_point("DM85:0.5,vero:0.5,tip=3mm");
  const auto measured = predict_spectrum(model, point, "office", kResponse);
  const auto c = compare_with_baselines(model, point, "office", kResponse, measured);
  EXPECT_NEAR(c.interpolated.rms_db, 0.0, 1e-9);
  ASSERT_EQ(c.baselines.size(), 4u);
  for (const auto& b : c.baselines) {
    // Each baseline's error is, bin for bin, the difference of the log gains: checked against
    // interpolated_log_gain directly (an independent path through the curves).
    const auto own = interpolated_log_gain(model, point, model.frequencies_hz);
    const auto theirs = interpolated_log_gain(model, b.corner, model.frequencies_hz);
    double sum = 0;
    for (std::size_t j = 0; j < own.size(); ++j) {
      const double db = 20.0 / std::log(10.0) * (theirs[j] - own[j]);
      sum += db * db;
    }
    EXPECT_NEAR(b.error.rms_db, std::sqrt(sum / static_cast<double>(own.size())), 1e-9)
        << to_string(b.corner);
    EXPECT_EQ(b.error.rms_db_by_speed.size(), model.speeds_m_s.size());
  }
  EXPECT_TRUE(c.beats_every_baseline());
}

TEST(CompareWithBaselines, AMeasurementThatIsACornerIsNotBeaten) {
  const auto model = hand_made_model();
  const auto point = parse_design_point("DM95,tip=1.5mm");
  const auto measured =
      predict_spectrum(model, parse_design_point("DM95,tip=2mm"), "office", kResponse);
  const auto c = compare_with_baselines(model, point, "office", kResponse, measured);
  ASSERT_EQ(c.baselines.size(), 2u);
  EXPECT_NEAR(c.baselines[1].error.rms_db, 0.0, 1e-9);
  EXPECT_GT(c.interpolated.rms_db, 0.0);
  EXPECT_FALSE(c.beats_every_baseline());
}

TEST(CompareWithBaselines, AFittedDesignHasNoBaselineToBeat) {
  const auto model = hand_made_model();
  const auto point = parse_design_point("vero,tip=2mm");
  const auto measured = predict_spectrum(model, point, "office", kResponse);
  const auto c = compare_with_baselines(model, point, "office", kResponse, measured);
  EXPECT_TRUE(c.baselines.empty());
  EXPECT_FALSE(c.beats_every_baseline());
}

}  // namespace
}  // namespace nibrig::model::design
