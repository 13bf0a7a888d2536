// The design loop's parts against independent references: the prints' correction (a Gaussian
// process, checked against its two-print posterior written out by hand, and its model-error scale
// against the closed-form maximum), the just-noticeable distance against Φ⁻¹, the measurement's
// noise against the nail pairs' descriptors read directly, and the stopping rule's reasons.
#include "model/design/design_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "model/design/design_search.hpp"
#include "model/design/loop_folder.hpp"
#include "model/design/print_discrepancy.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/format_error.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

DesignPoint loop_test_point(double dm85, double tip_mm) {
  DesignPoint p;
  if (dm85 < 1) p.mix.push_back({"vero", 1 - dm85});
  if (dm85 > 0) p.mix.push_back({"DM85", dm85});
  p.tip_diameter_m = tip_mm * 1e-3;
  return p;
}

DiscrepancyPrior diagonal_prior(double c0, double c1, double r0, double r1) {
  DiscrepancyPrior prior;
  prior.names = {"friction_mu", "log10_weighted_mean_vibration"};
  prior.model_error = Eigen::Vector2d(c0, c1).asDiagonal();
  prior.measurement_noise = Eigen::Vector2d(r0, r1).asDiagonal();
  prior.second_material = "DM85";
  return prior;
}

TEST(PrintDiscrepancy, TwoPrintsGiveTheGaussianProcessPosteriorWrittenOut) {
  // Residuals small against C, so the likeliest scale of C is its floor, 1.
  const auto prior = diagonal_prior(0.01, 0.04, 0.002, 0.005);
  const DesignPoint a = loop_test_point(0.2, 1.5), b = loop_test_point(0.7, 3.0),
                    x = loop_test_point(0.5, 2.0);
  const Eigen::Vector2d ra(0.001, -0.002), rb(-0.0005, 0.003);
  const PrintDiscrepancy discrepancy(prior, {{a, ra}, {b, rb}});
  ASSERT_DOUBLE_EQ(discrepancy.model_error_scale(), 1.0);
  const auto k = [](const DesignPoint& p, const DesignPoint& q) {
    const double df = (p.fraction_of("DM85") - q.fraction_of("DM85")) / 0.5;
    const double dt = (p.tip_diameter_m - q.tip_diameter_m) / 0.0015;
    return std::exp(-0.5 * (df * df + dt * dt));
  };
  const auto correction = discrepancy.at(x);
  // Each descriptor alone (C and R diagonal): mean c·kᵀ(cK + rI)⁻¹y, variance c − c²·kᵀ(cK +
  // rI)⁻¹k, with the 2 × 2 inverse by its adjugate.
  for (int d = 0; d < 2; ++d) {
    const double c = prior.model_error(d, d), r = prior.measurement_noise(d, d);
    const double m11 = c * k(a, a) + r, m12 = c * k(a, b), m22 = c * k(b, b) + r;
    const double det = m11 * m22 - m12 * m12;
    const double ka = k(x, a), kb = k(x, b);
    const double wa = (m22 * ka - m12 * kb) / det, wb = (m11 * kb - m12 * ka) / det;
    // Both are exact solutions of one small well-conditioned system: round-off apart.
    EXPECT_NEAR(correction.mean(d), c * (wa * ra(d) + wb * rb(d)), 1e-12) << "descriptor " << d;
    EXPECT_NEAR(correction.covariance(d, d), c - c * c * (wa * ka + wb * kb), 1e-12)
        << "descriptor " << d;
  }
  EXPECT_NEAR(correction.covariance(0, 1), 0.0, 1e-15);
  // Far from both prints (a tip 20 correlation lengths away) nothing is corrected.
  const auto far = discrepancy.at(loop_test_point(0.5, 32.0));
  EXPECT_NEAR(far.mean.norm(), 0.0, 1e-12);
  EXPECT_NEAR(far.covariance(1, 1), prior.model_error(1, 1), 1e-12);
}

TEST(PrintDiscrepancy, ResidualsBeyondTheModelErrorScaleItUpByTheirLikeliestScale) {
  // One print, C = I, R = 0: the likelihood of r under N(0, s·I) peaks at s = |r|² / 2.
  const auto prior = diagonal_prior(1.0, 1.0, 0.0, 0.0);
  const PrintDiscrepancy discrepancy(prior,
                                     {{loop_test_point(0.5, 2.0), Eigen::Vector2d(3.0, -4.0)}});
  // The golden-section search stops within 1e-4 of the log of the scale.
  EXPECT_NEAR(discrepancy.model_error_scale(), 12.5, 12.5 * 2e-4);
  // At the print itself, with no measurement noise, the correction is the residual.
  EXPECT_NEAR(discrepancy.at(loop_test_point(0.5, 2.0)).mean(1), -4.0, 1e-6);
}

TEST(PrintDiscrepancy, MatricesOfTheWrongSizeAndResidualsThatAreNotFiniteAreRefused) {
  auto prior = diagonal_prior(1.0, 1.0, 0.0, 0.0);
  EXPECT_THROW(PrintDiscrepancy(prior, {{loop_test_point(0.5, 2.0), Eigen::Vector3d(1, 2, 3)}}),
               std::invalid_argument);
  EXPECT_THROW(PrintDiscrepancy(prior, {{loop_test_point(0.5, 2.0), Eigen::Vector2d(NAN, 0)}}),
               std::invalid_argument);
  prior.measurement_noise = Eigen::Matrix3d::Identity();
  EXPECT_THROW(PrintDiscrepancy(prior, {}), std::invalid_argument);
}

TEST(MeasurementDescriptorNoise,
     IsHalfTheNailPairsSquaredDifferenceAndTheFrictionIntervalsVariance) {
  const io::Catalog catalog = io::read_catalog(io::default_catalog());
  const std::vector<std::string> names = space::paper_descriptor_names(2);
  const Eigen::MatrixXd noise = measurement_descriptor_noise(catalog, names);
  // The reference, read straight from the pairings: log10 of each nail pair's weighted mean.
  double square = 0.0;
  int pairs = 0;
  for (const auto& a : catalog.pairings)
    for (const auto& b : catalog.pairings)
      if (a.surface == b.surface && a.tool.size() > 6 &&
          a.tool.substr(a.tool.size() - 6) == "_nail1" &&
          b.tool == a.tool.substr(0, a.tool.size() - 1) + "2") {
        const double d =
            std::log10(a.vibration->weighted_mean) - std::log10(b.vibration->weighted_mean);
        square += d * d;
        ++pairs;
      }
  ASSERT_EQ(pairs, 3);  // DM85 1, 2 and 4 mm on note paper
  EXPECT_NEAR(noise(1, 1), square / (2 * pairs), 1e-15);
  double variance = 0.0;
  int measured = 0;
  for (const auto& p : catalog.pairings)
    if (p.friction && p.friction->mu_ci_high > p.friction->mu_ci_low) {
      variance +=
          std::pow((p.friction->mu_ci_high - p.friction->mu_ci_low) / (2 * 1.959963984540054), 2);
      ++measured;
    }
  EXPECT_NEAR(noise(0, 0), variance / measured, 1e-15);
  EXPECT_EQ(noise(0, 1), 0.0);
}

TEST(JustNoticeableDistance, IsTheProbitsQuartileOverItsScale) {
  space::JudgmentModel paper;  // the paper's probit, s = 2/3
  // Φ(s·d) = 0.75: d = Φ⁻¹(0.75) / s, Φ⁻¹(0.75) = 0.6744897501960817.
  EXPECT_NEAR(just_noticeable_distance(paper, 2), 0.6744897501960817 / paper.scale, 1e-9);
  space::JudgmentModel lapsed = paper;
  lapsed.lapse = 0.1;  // inattention is not the sound's: the same distance
  EXPECT_NEAR(just_noticeable_distance(lapsed, 2), just_noticeable_distance(paper, 2), 1e-12);
}

TEST(LoopStop, SaysWhyWithinTheThresholdThenNoUntriedDesignWorthAPrintThenTheRoundLimit) {
  EXPECT_EQ(loop_stop({}, 1.0, 3, nullptr), LoopStop::none);
  EXPECT_EQ(loop_stop({1.5, 0.9}, 1.0, 2, nullptr), LoopStop::within_threshold);
  EXPECT_EQ(loop_stop({1.5, 1.2}, 1.0, 2, nullptr), LoopStop::round_limit);
  Proposal next;
  next.search.evaluated.resize(3);
  next.search.evaluated[0].distance = 1.4;
  next.search.evaluated[1].distance = 1.25;
  next.search.evaluated[2].distance = 1.19;  // printed already: it does not count
  next.printed = {false, false, true};
  next.chances = {0.02, 0.05, 0.4};
  // No untried design is predicted nearer than the nearest print measured (1.2), and none has a
  // chance in ten of landing within the threshold.
  EXPECT_EQ(loop_stop({1.5, 1.2}, 1.0, 6, &next), LoopStop::no_closer_design);
  next.chances[1] = 0.15;  // one has: the loop goes on
  EXPECT_EQ(loop_stop({1.5, 1.2}, 1.0, 6, &next), LoopStop::none);
  next.chances[1] = 0.05;
  next.search.evaluated[1].distance = 1.1;  // one is predicted nearer
  EXPECT_EQ(loop_stop({1.5, 1.2}, 1.0, 6, &next), LoopStop::none);
  next.printed = {true, true, true};  // nothing left untried
  EXPECT_EQ(loop_stop({1.5, 1.2}, 1.0, 6, &next), LoopStop::no_closer_design);
  EXPECT_EQ(parse_next_print_rule(rule_name(NextPrintRule::predicted_optimum)),
            NextPrintRule::predicted_optimum);
  EXPECT_THROW(parse_next_print_rule("best"), std::invalid_argument);
}

// A loop's candidates are kept in loop.json and read back as the same designs; one of a material
// outside the loop's mix is refused by name, and a file's malformed candidate names its place.
TEST(LoopFolder, ARequestsCandidatesAreKeptAndOnesOutsideItsMixRefused) {
  LoopRequest r;
  r.target = "DM952/glass";
  r.surface = "glass";
  r.space_file = "space.json";
  r.candidates = {loop_test_point(0, 1), loop_test_point(1, 4), loop_test_point(0.25, 2)};
  check_loop_request(r);
  const auto folder = nibrig::test::scratch_dir("loop_folder_candidates");
  write_loop_request(folder, r);
  const LoopRequest back = read_loop_request(folder);
  ASSERT_EQ(back.candidates.size(), r.candidates.size());
  for (std::size_t i = 0; i < r.candidates.size(); ++i)
    EXPECT_TRUE(same_design(back.candidates[i], r.candidates[i])) << i;

  LoopRequest other = r;
  other.candidates.push_back(parse_design_point("DM95,tip=2mm"));
  try {
    check_loop_request(other);
    ADD_FAILURE() << "a DM95 candidate in a vero-DM85 loop was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("DM95"), std::string::npos) << e.what();
  }
  // The second candidate's text cut short, as a hand edit might leave it.
  std::ifstream in(loop_request_file(folder));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string second = "\"" + to_string(r.candidates[1]) + "\"";
  ASSERT_NE(text.find(second), std::string::npos) << text;
  text.replace(text.find(second), second.size(), "\"vero,tip=\"");
  std::ofstream(loop_request_file(folder)) << text;
  try {
    read_loop_request(folder);
    ADD_FAILURE() << "a malformed candidate was read";
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("candidates[1]"), std::string::npos) << e.what();
  }
}
}  // namespace
}  // namespace nibrig::model::design
