// The fit of Eq. 10 on synthetic data: it recovers a known model, its elimination of F agrees with
// a brute-force least-squares solve that keeps F as unknowns, the gauge leaves t and m alone, and
// data that cannot pin a curve are refused by name.
#include "model/forcing/forcing_fit.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <map>

#include "tests/model/forcing/synthetic_exemplars.hpp"

namespace nibrig::model::forcing {
namespace {

using test::add_log_noise;
using test::make_synthetic_truth;

TEST(ForcingFit, RecoversTheModelThatMadeNoiseFreeData) {
  const auto truth = make_synthetic_truth();
  const ForcingModel model = fit_forcing_model(truth.exemplars);
  // Exact data and a full-rank linear problem: only round-off separates the fit from the truth.
  for (const auto& [d, knots] : truth.tip) {
    const auto& fitted = model.tip_curve(d);
    for (std::size_t k = 0; k < knots.size(); ++k)
      EXPECT_NEAR(fitted[k], knots[k], 1e-9) << "tip " << d << " knot " << k;
  }
  for (const auto& [m, knots] : truth.material) {
    const auto& fitted = model.material_curve(m);
    for (std::size_t k = 0; k < knots.size(); ++k)
      EXPECT_NEAR(fitted[k], knots[k], 1e-9) << "material " << m << " knot " << k;
  }
  for (const auto& [surface, rows] : truth.forcing)
    for (std::size_t s = 0; s < rows.size(); ++s)
      for (std::size_t j = 0; j < rows[s].size(); ++j)
        EXPECT_NEAR(std::log(model.surface_forcing.at(surface)[s][j]), std::log(rows[s][j]), 1e-9);
  EXPECT_LT(model.residual_rms_db, 1e-8);
  EXPECT_EQ(model.exemplar_count(), truth.exemplars.size());
  EXPECT_EQ(model.observations, truth.exemplars.size() * 2 * 25);
  EXPECT_EQ(model.skipped_nonpositive, 0u);
  EXPECT_EQ(model.tip_curve(0.002), std::vector<double>(11, 0.0));  // the pins
  EXPECT_EQ(model.material_curve("vero"), std::vector<double>(11, 0.0));
}

// The whole problem written out: one unknown per surface cell (ln F) and per free knot, one row
// per positive observation, solved by a rank-revealing QR with no elimination.
struct BruteForce {
  std::map<std::string, Eigen::VectorXd> knots;  // "tip 1", "tip 4", "DM95", "DM85"
  std::map<std::string, std::vector<std::vector<double>>> log_forcing;
};

BruteForce brute_force_fit(const std::vector<ForcingExemplar>& exemplars) {
  const std::vector<double> knots = default_knot_frequencies();
  const auto K = static_cast<Eigen::Index>(knots.size());
  const std::vector<std::string> blocks{"tip 1", "tip 4", "DM95", "DM85"};
  const auto& grid = exemplars.front().measured;
  const std::size_t speeds = grid.speeds_m_s.size(), bins = grid.frequencies_hz.size();
  std::map<std::string, Eigen::Index> surface_base;
  Eigen::Index columns = static_cast<Eigen::Index>(blocks.size()) * K;
  for (const auto& e : exemplars)
    if (!surface_base.count(e.surface)) {
      surface_base[e.surface] = columns;
      columns += static_cast<Eigen::Index>(speeds * bins);
    }
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<double> rhs;
  for (const auto& e : exemplars)
    for (std::size_t s = 0; s < speeds; ++s)
      for (std::size_t j = 0; j < bins; ++j) {
        const double a = e.measured.amplitude_m_s2[s][j];
        if (!(a > 0)) continue;
        Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(columns);
        row(surface_base[e.surface] + static_cast<Eigen::Index>(s * bins + j)) = 1.0;
        const auto weights = hermite_weights(knots, grid.frequencies_hz[j]);
        auto add_block = [&](const std::string& name, double share) {
          const auto b = std::find(blocks.begin(), blocks.end(), name) - blocks.begin();
          for (const auto& [k, w] : weights) row(b * K + static_cast<Eigen::Index>(k)) += share * w;
        };
        // Tips 1, 2 (the reference, no block) and 4 mm; between them, by hand, linear in the
        // diameter.
        const double d_mm = e.tip_diameter_m * 1e3;
        if (d_mm <= 2.0)
          add_block("tip 1", (2.0 - d_mm) / 1.0);
        else
          add_block("tip 4", (d_mm - 2.0) / 2.0);
        if (e.mix.empty()) {
          if (e.material != "vero") add_block(e.material, 1.0);
        } else {
          for (const auto& [m, f] : e.mix)
            if (m != "vero") add_block(m, f);
        }
        rows.push_back(row);
        rhs.push_back(std::log(a) - std::log(e.response_magnitude[j]));
      }
  Eigen::MatrixXd a(static_cast<Eigen::Index>(rows.size()), columns);
  Eigen::VectorXd b(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    a.row(static_cast<Eigen::Index>(r)) = rows[r];
    b(static_cast<Eigen::Index>(r)) = rhs[r];
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  EXPECT_EQ(qr.rank(), columns) << "the synthetic design must determine every unknown";
  const Eigen::VectorXd x = qr.solve(b);
  BruteForce out;
  for (std::size_t b = 0; b < blocks.size(); ++b)
    out.knots[blocks[b]] = x.segment(static_cast<Eigen::Index>(b) * K, K);
  for (const auto& [surface, base] : surface_base) {
    auto& f = out.log_forcing[surface];
    for (std::size_t s = 0; s < speeds; ++s) {
      f.emplace_back();
      for (std::size_t j = 0; j < bins; ++j)
        f.back().push_back(x(base + static_cast<Eigen::Index>(s * bins + j)));
    }
  }
  return out;
}

TEST(ForcingFit, EliminatingTheForcingGivesTheFullLeastSquaresSolution) {
  auto truth = make_synthetic_truth(21);
  add_log_noise(truth.exemplars, 0.3, 5);
  // Two amplitudes with no logarithm: both solvers must leave the same observations out.
  truth.exemplars[3].measured.amplitude_m_s2[1][7] = 0.0;
  truth.exemplars[12].measured.amplitude_m_s2[0][20] = -1e-3;
  const ForcingModel model = fit_forcing_model(truth.exemplars);
  const BruteForce reference = brute_force_fit(truth.exemplars);
  EXPECT_EQ(model.skipped_nonpositive, 2u);
  EXPECT_EQ(model.observations, truth.exemplars.size() * 2 * 25 - 2);
  // Both are exact solutions of the same well-conditioned least-squares problem; they differ by
  // round-off of the two factorisations (condition numbers ~1e3 here).
  auto expect_curve = [&](const std::vector<double>& fitted, const Eigen::VectorXd& ref,
                          const std::string& name) {
    for (std::size_t k = 0; k < fitted.size(); ++k)
      EXPECT_NEAR(fitted[k], ref(static_cast<Eigen::Index>(k)), 1e-9) << name << " knot " << k;
  };
  expect_curve(model.tip_curve(0.001), reference.knots.at("tip 1"), "tip 1 mm");
  expect_curve(model.tip_curve(0.004), reference.knots.at("tip 4"), "tip 4 mm");
  expect_curve(model.material_curve("DM95"), reference.knots.at("DM95"), "DM95");
  expect_curve(model.material_curve("DM85"), reference.knots.at("DM85"), "DM85");
  for (const auto& [surface, rows] : reference.log_forcing)
    for (std::size_t s = 0; s < rows.size(); ++s)
      for (std::size_t j = 0; j < rows[s].size(); ++j)
        EXPECT_NEAR(std::log(model.surface_forcing.at(surface)[s][j]), rows[s][j], 1e-9);
  // Noise of σ = 0.3 in ln amplitude is 2.6 dB; the fit absorbs a part of it (one F per cell), so
  // the residual sits below that but well above zero.
  EXPECT_GT(model.residual_rms_db, 1.0);
  EXPECT_LT(model.residual_rms_db, 20 / std::log(10.0) * 0.3);
}

// A design loop's prints: a mix at a tip between the fitted ones, made from the same truth (ln m
// the fractions' sum, ln t linear in the diameter) and then measured with noise.
ForcingExemplar synthetic_mixed_print(const test::SyntheticTruth& truth, const std::string& surface,
                                      std::vector<std::pair<std::string, double>> mix,
                                      double tip_m) {
  ForcingExemplar e = truth.exemplars.front();
  e.tool = "loop print";
  e.surface = surface;
  e.material = "mix";
  e.mix = std::move(mix);
  e.tip_diameter_m = tip_m;
  e.tip_interpolated = true;
  e.response_magnitude = test::synthetic_response(e.measured.frequencies_hz, 90 + 3e3 * tip_m + 3);
  const double lower = tip_m <= 0.002 ? 0.001 : 0.002, upper = tip_m <= 0.002 ? 0.002 : 0.004;
  const double w = (tip_m - lower) / (upper - lower);
  for (std::size_t s = 0; s < e.measured.speeds_m_s.size(); ++s)
    for (std::size_t j = 0; j < e.measured.frequencies_hz.size(); ++j) {
      const double f = e.measured.frequencies_hz[j];
      double gain = (1 - w) * hermite_value(truth.knots, truth.tip.at(lower), f) +
                    w * hermite_value(truth.knots, truth.tip.at(upper), f);
      for (const auto& [m, share] : e.mix)
        gain += share * hermite_value(truth.knots, truth.material.at(m), f);
      e.measured.amplitude_m_s2[s][j] =
          e.response_magnitude[j] * truth.forcing.at(surface)[s][j] * std::exp(gain);
    }
  return e;
}

TEST(ForcingFit, AMixedPrintAtAnInterpolatedTipIsFittedAsAPredictionWouldMakeIt) {
  auto truth = make_synthetic_truth(9);
  truth.exemplars.push_back(
      synthetic_mixed_print(truth, "a", {{"DM95", 0.4}, {"DM85", 0.6}}, 0.003));
  truth.exemplars.push_back(
      synthetic_mixed_print(truth, "b", {{"vero", 0.25}, {"DM85", 0.75}}, 0.0015));
  // Noise-free: the fit stays exact, the prints adding no tip curve of their own.
  const ForcingModel exact = fit_forcing_model(truth.exemplars);
  EXPECT_EQ(exact.tip_log_gain.size(), 3u);
  EXPECT_LT(exact.residual_rms_db, 1e-8);
  for (const auto& [m, knots] : truth.material)
    for (std::size_t k = 0; k < knots.size(); ++k)
      EXPECT_NEAR(exact.material_curve(m)[k], knots[k], 1e-9) << m << " knot " << k;
  // With noise, the elimination of F against every unknown written out (brute_force_fit weighs
  // the prints' rows by hand): one least-squares problem, equal to round-off.
  add_log_noise(truth.exemplars, 0.3, 11);
  const ForcingModel model = fit_forcing_model(truth.exemplars);
  const BruteForce reference = brute_force_fit(truth.exemplars);
  for (const auto& [name, curve] :
       std::map<std::string, std::vector<double>>{{"tip 1", model.tip_curve(0.001)},
                                                  {"tip 4", model.tip_curve(0.004)},
                                                  {"DM95", model.material_curve("DM95")},
                                                  {"DM85", model.material_curve("DM85")}})
    for (std::size_t k = 0; k < curve.size(); ++k)
      EXPECT_NEAR(curve[k], reference.knots.at(name)(static_cast<Eigen::Index>(k)), 1e-9)
          << name << " knot " << k;
}

TEST(ForcingFit, AnInterpolatedTipOutsideTheFittedTipsIsRefused) {
  auto truth = make_synthetic_truth();
  auto print = synthetic_mixed_print(truth, "a", {{"DM95", 0.5}, {"DM85", 0.5}}, 0.003);
  print.tip_diameter_m = 0.005;
  truth.exemplars.push_back(print);
  const auto problems = fit_problems(truth.exemplars);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find(
                "loop print on a: its tip, 5 mm, lies outside the fitted tips (1 mm to 4 mm)"),
            std::string::npos)
      << problems[0];
  auto unbalanced = make_synthetic_truth();
  unbalanced.exemplars.push_back(
      synthetic_mixed_print(unbalanced, "a", {{"DM95", 0.5}, {"DM85", 0.4}}, 0.003));
  EXPECT_THROW(fit_forcing_model(unbalanced.exemplars), std::invalid_argument);
}

TEST(ForcingFit, AConstantFactorOnAllDataMovesOnlyTheForcing) {
  auto truth = make_synthetic_truth(4);
  add_log_noise(truth.exemplars, 0.2, 9);
  const ForcingModel before = fit_forcing_model(truth.exemplars);
  for (auto& e : truth.exemplars)
    for (auto& row : e.measured.amplitude_m_s2)
      for (double& a : row) a *= 37.0;
  const ForcingModel after = fit_forcing_model(truth.exemplars);
  for (const auto& [d, knots] : before.tip_log_gain)
    for (std::size_t k = 0; k < knots.size(); ++k)
      EXPECT_NEAR(after.tip_curve(d)[k], knots[k], 1e-10);
  for (const auto& [m, knots] : before.material_log_gain)
    for (std::size_t k = 0; k < knots.size(); ++k)
      EXPECT_NEAR(after.material_curve(m)[k], knots[k], 1e-10);
  for (const auto& [surface, rows] : before.surface_forcing)
    for (std::size_t s = 0; s < rows.size(); ++s)
      for (std::size_t j = 0; j < rows[s].size(); ++j)
        EXPECT_NEAR(after.surface_forcing.at(surface)[s][j] / rows[s][j], 37.0, 37.0 * 1e-10);
  EXPECT_NEAR(after.residual_rms_db, before.residual_rms_db, 1e-9);
}

TEST(ForcingFit, PredictGivesBackTheDataOfANoiseFreeFit) {
  const auto truth = make_synthetic_truth(2);
  const ForcingModel model = fit_forcing_model(truth.exemplars);
  const auto& e = truth.exemplars[5];
  const auto predicted =
      model.predict(e.response_magnitude, e.surface, e.tip_diameter_m, e.material);
  ASSERT_EQ(predicted.amplitude_m_s2.size(), 2u);
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t j = 0; j < predicted.frequencies_hz.size(); ++j)
      EXPECT_NEAR(predicted.amplitude_m_s2[s][j] / e.measured.amplitude_m_s2[s][j], 1.0, 1e-9);
  EXPECT_THROW(model.predict(e.response_magnitude, "glass", 0.002, "vero"), std::invalid_argument);
  EXPECT_THROW(model.predict(e.response_magnitude, "a", 0.003, "vero"), std::invalid_argument);
  EXPECT_THROW(model.predict(e.response_magnitude, "a", 0.002, "teflon"), std::invalid_argument);
  EXPECT_THROW(model.predict(std::vector<double>(3, 1.0), "a", 0.002, "vero"),
               std::invalid_argument);
  EXPECT_THROW(model.tip_log_gain_at(0.002, 501.0), std::invalid_argument);
}

TEST(ForcingFit, ACurveTheDataCannotSeparateIsRefusedByName) {
  auto truth = make_synthetic_truth();
  // A teflon tool measured alone on its own surface: its curve trades freely against that
  // surface's forcing.
  ForcingExemplar lonely = truth.exemplars.front();
  lonely.tool = "teflon2";
  lonely.material = "teflon";
  lonely.surface = "d";
  truth.exemplars.push_back(lonely);
  const auto problems = fit_problems(truth.exemplars);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("material 'teflon' is not identifiable"), std::string::npos)
      << problems[0];
  EXPECT_NE(problems[0].find("(d)"), std::string::npos) << problems[0];
  try {
    fit_forcing_model(truth.exemplars);
    FAIL() << "expected the fit to refuse";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("teflon"), std::string::npos) << e.what();
  }
}

TEST(ForcingFit, WithoutTheReferenceTipTheOtherTipsAreNotPinned) {
  auto truth = make_synthetic_truth();
  std::vector<ForcingExemplar> no_reference;
  for (const auto& e : truth.exemplars)
    if (std::abs(e.tip_diameter_m - 0.002) > 1e-9) no_reference.push_back(e);
  const auto problems = fit_problems(no_reference);
  ASSERT_EQ(problems.size(), 2u);  // tip 1 mm and tip 4 mm: only their difference is known
  for (const auto& p : problems)
    EXPECT_NE(p.find("no exemplar has the reference tip, 2 mm"), std::string::npos) << p;
}

TEST(ForcingFit, MismatchedDataAreRefused) {
  auto truth = make_synthetic_truth();
  EXPECT_THROW(fit_forcing_model(std::vector<ForcingExemplar>{}), std::invalid_argument);
  auto short_response = truth.exemplars;
  short_response[2].response_magnitude.pop_back();
  const auto problems = fit_problems(short_response);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems[0].find(short_response[2].tool + " on " + short_response[2].surface),
            std::string::npos)
      << problems[0];
  auto other_grid = truth.exemplars;
  other_grid[4].measured.frequencies_hz[3] += 1.0;
  EXPECT_THROW(fit_forcing_model(other_grid), std::invalid_argument);
  auto beyond = truth.exemplars;
  for (auto& e : beyond) e.measured.frequencies_hz.back() = 510;
  EXPECT_THROW(fit_forcing_model(beyond), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::forcing
