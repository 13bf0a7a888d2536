// Prediction of a design from a forcing model, checked on a hand-made model whose curves are known
// in closed form (no FEM): at a fitted tip and material it must equal the model's own prediction,
// between them it must follow the stated linear rules, and outside it must refuse.
#include "model/design/predicted_tool.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "model/forcing/hermite_curve.hpp"
#include "tests/model/design/hand_made_forcing_model.hpp"

namespace nibrig::model::design {
namespace {

using ::testing::HasSubstr;

TEST(PredictedTool, AtAFittedDesignItIsTheModelsOwnPrediction) {
  const auto model = hand_made_model();
  for (const auto& [tip, name] : std::vector<std::pair<double, std::string>>{
           {0.001, "DM85"}, {0.004, "DM95"}, {0.002, "vero"}}) {
    const auto expected = model.predict(kResponse, "office", tip, name);
    const auto got = predict_spectrum(model, DesignPoint{{{name, 1.0}}, tip}, "office", kResponse);
    for (std::size_t s = 0; s < expected.amplitude_m_s2.size(); ++s)
      for (std::size_t j = 0; j < kResponse.size(); ++j)
        EXPECT_NEAR(got.amplitude_m_s2[s][j], expected.amplitude_m_s2[s][j],
                    1e-12 * expected.amplitude_m_s2[s][j]);
  }
}

TEST(PredictedTool, BetweenFittedDesignsTheLogGainsAreLinear) {
  const auto model = hand_made_model();
  const DesignPoint point{{{"DM85", 0.25}, {"vero", 0.75}}, 0.003};  // halfway from 2 to 4 mm
  const auto gain = interpolated_log_gain(model, point, model.frequencies_hz);
  for (std::size_t j = 0; j < model.frequencies_hz.size(); ++j) {
    const double f = model.frequencies_hz[j];
    const double tip =
        0.5 * forcing::hermite_value(model.knot_frequencies_hz, model.tip_log_gain.at(0.004), f);
    const double material = 0.25 * forcing::hermite_value(model.knot_frequencies_hz,
                                                          model.material_log_gain.at("DM85"), f);
    EXPECT_NEAR(gain[j], tip + material, 1e-12) << f << " Hz";
  }
}

TEST(PredictedTool, RefusesToExtrapolateAndNamesWhatIsMissing) {
  const auto model = hand_made_model();
  try {
    interpolated_log_gain(model, DesignPoint{{{"vero", 1.0}}, 0.005}, model.frequencies_hz);
    FAIL() << "a 5 mm tip is beyond the fitted 4 mm";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("1 mm above the largest"));
    EXPECT_THAT(e.what(), HasSubstr("1 mm to 4 mm"));
  }
  EXPECT_THROW(
      interpolated_log_gain(model, DesignPoint{{{"wood", 1.0}}, 0.002}, model.frequencies_hz),
      std::invalid_argument);
  EXPECT_THROW(predict_spectrum(model, DesignPoint{{{"vero", 1.0}}, 0.002}, "glass", kResponse),
               std::invalid_argument);
}

io::Catalog friction_catalog() {
  io::Catalog c;
  auto tool = [&](std::string id, std::string material, double tip, double mu) {
    c.tools.push_back({id, id, "printed", material, tip});
    io::Pairing p;
    p.tool = id;
    p.surface = "office";
    p.friction = io::FrictionDescriptor{};
    p.friction->mu = mu;
    c.pairings.push_back(p);
  };
  tool("vero1", "vero", 0.001, 0.10);
  tool("vero4", "vero", 0.004, 0.16);
  tool("DM851", "DM85", 0.001, 0.50);
  tool("DM854", "DM85", 0.004, 0.80);
  tool("DM851_nail1", "DM85", 0.001, 9.0);  // a worn variant: never used
  c.surfaces.push_back({"office", "office"});
  return c;
}

TEST(PredictedTool, FrictionIsLinearInTipAndFractions) {
  const auto catalog = friction_catalog();
  EXPECT_NEAR(interpolated_friction(catalog, {{{"vero", 1.0}}, 0.001}, "office").mu, 0.10, 1e-12);
  EXPECT_NEAR(interpolated_friction(catalog, {{{"vero", 1.0}}, 0.002}, "office").mu, 0.12, 1e-12);
  // 0.25 · μ_DM85(2 mm) + 0.75 · μ_vero(2 mm) = 0.25 · 0.6 + 0.75 · 0.12
  EXPECT_NEAR(
      interpolated_friction(catalog, {{{"DM85", 0.25}, {"vero", 0.75}}, 0.002}, "office").mu,
      0.25 * 0.6 + 0.75 * 0.12, 1e-12);
  // Measured: one material at a measured tip; anything else is an interpolation.
  EXPECT_TRUE(interpolated_friction(catalog, {{{"vero", 1.0}}, 0.001}, "office").measured);
  EXPECT_FALSE(interpolated_friction(catalog, {{{"vero", 1.0}}, 0.0015}, "office").measured);
  EXPECT_FALSE(
      interpolated_friction(catalog, {{{"DM85", 0.25}, {"vero", 0.75}}, 0.001}, "office").measured);
  EXPECT_THROW(interpolated_friction(catalog, {{{"DM95", 1.0}}, 0.002}, "office"),
               std::invalid_argument);
  EXPECT_THROW(interpolated_friction(catalog, {{{"vero", 1.0}}, 0.0005}, "office"),
               std::invalid_argument);
  EXPECT_THROW(interpolated_friction(catalog, {{{"vero", 1.0}}, 0.002}, "glass"),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::design
