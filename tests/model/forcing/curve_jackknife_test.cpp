// The delete-one-tool jackknife of the fitted curves, against the truth it must reproduce: zero
// spread on noise-free data, and on noisy data a standard error that matches the spread of the
// curves over many independent data sets drawn from the same truth (a Monte Carlo reference).
#include "model/forcing/curve_jackknife.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/forcing/hermite_curve.hpp"
#include "tests/model/forcing/synthetic_exemplars.hpp"

namespace nibrig::model::forcing {
namespace {

TEST(CurveJackknife, NoiseFreeDataLeaveNoSpread) {
  const auto truth = test::make_synthetic_truth();
  const CurveJackknife jack = jackknife_curves(truth.exemplars);
  EXPECT_EQ(jack.tools.size(), 9u);  // {vero, DM95, DM85} x {1, 2, 4 mm}
  EXPECT_TRUE(jack.not_left_out.empty());
  for (double d : {0.001, 0.002, 0.004})
    for (double se : jack.tip_standard_errors(d)) EXPECT_NEAR(se, 0.0, 1e-9) << d;
  for (const std::string m : {"vero", "DM95", "DM85"})
    for (double se : jack.material_standard_errors(m)) EXPECT_NEAR(se, 0.0, 1e-9) << m;
}

// Every exemplar of a tool gets the same smooth quirk (its print: shared across surfaces), and
// every bin its own noise.
void add_tool_quirks(std::vector<ForcingExemplar>& exemplars, double quirk_sigma, double bin_sigma,
                     std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const auto knots = default_knot_frequencies();
  std::map<std::string, std::vector<double>> quirk;
  for (auto& e : exemplars) {
    if (quirk.count(e.tool) == 0) {
      std::vector<double> values;
      for (std::size_t k = 0; k < knots.size(); ++k) values.push_back(quirk_sigma * normal(rng));
      quirk[e.tool] = values;
    }
    for (auto& row : e.measured.amplitude_m_s2)
      for (std::size_t j = 0; j < row.size(); ++j)
        row[j] *= std::exp(hermite_value(knots, quirk[e.tool], e.measured.frequencies_hz[j]) +
                           bin_sigma * normal(rng));
  }
}

TEST(CurveJackknife, StandardErrorsMatchTheSpreadOverIndependentDataSets) {
  const auto truth = test::make_synthetic_truth();
  std::mt19937 rng(2026);
  constexpr int kDataSets = 60;
  // Knots of the non-reference curves: (tip 1 mm, tip 4 mm, DM95, DM85) × 11.
  const auto statistics = [](const CurveReplicate& r) {
    std::vector<double> v;
    for (double d : {0.001, 0.004})
      for (double k : r.tip.at(d)) v.push_back(k);
    for (const std::string m : {"DM95", "DM85"})
      for (double k : r.material.at(m)) v.push_back(k);
    return v;
  };
  std::vector<double> sum, sum_squares, jackknife_sum;
  for (int n = 0; n < kDataSets; ++n) {
    auto exemplars = truth.exemplars;
    add_tool_quirks(exemplars, 0.15, 0.1, rng);
    const ForcingModel model = fit_forcing_model(exemplars);
    const auto fitted = statistics({model.tip_log_gain, model.material_log_gain});
    const CurveJackknife jack = jackknife_curves(exemplars);
    ASSERT_EQ(jack.replicates.size(), 9u);
    if (sum.empty()) sum.assign(fitted.size(), 0.0), sum_squares = sum, jackknife_sum = sum;
    for (std::size_t i = 0; i < fitted.size(); ++i) {
      sum[i] += fitted[i];
      sum_squares[i] += fitted[i] * fitted[i];
      jackknife_sum[i] +=
          jack.standard_error([&](const CurveReplicate& r) { return statistics(r)[i]; });
    }
  }
  // Over all knots: the mean jackknife standard error against the Monte Carlo standard deviation.
  // The jackknife variance runs high on average (the Efron-Stein inequality), the more so with
  // few, unequal groups (nine tools here): 1.40 when written. Within a factor of 1.6 either way is
  // agreement; the classic slip, the variance's (n−1) factor left out, gives 1.40/√8 ≈ 0.5.
  double monte_carlo = 0.0, jackknife = 0.0;
  for (std::size_t i = 0; i < sum.size(); ++i) {
    const double mean = sum[i] / kDataSets;
    monte_carlo += std::sqrt(sum_squares[i] / kDataSets - mean * mean);
    jackknife += jackknife_sum[i] / kDataSets;
  }
  const double ratio = jackknife / monte_carlo;
  std::printf("jackknife SE / Monte Carlo SD over %zu knots: %.3f (mean SD %.4f)\n", sum.size(),
              ratio, monte_carlo / static_cast<double>(sum.size()));
  EXPECT_GT(ratio, 1 / 1.6);
  EXPECT_LT(ratio, 1.6);
}

TEST(CurveJackknife, TheOnlyToolOfACurveCannotBeLeftOut) {
  auto truth = test::make_synthetic_truth();
  // Rename the 4 mm DM85 tool "teflon": it is then the only tool of its material.
  for (auto& e : truth.exemplars)
    if (e.material == "DM85" && same_tip(e.tip_diameter_m, 0.004))
      e.material = "teflon", e.tool = "teflon4";
  const CurveJackknife jack = jackknife_curves(truth.exemplars);
  EXPECT_EQ(jack.tools.size(), 8u);
  ASSERT_EQ(jack.not_left_out.size(), 1u);
  EXPECT_EQ(jack.not_left_out.front(), "teflon4: no other tool is of teflon");
  EXPECT_THROW(CurveJackknife{}.standard_error([](const CurveReplicate&) { return 0.0; }),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::forcing
