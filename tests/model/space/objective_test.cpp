#include "model/space/objective.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/space/normal_tail.hpp"
#include "tests/model/space/study_fixture.hpp"

namespace nibrig::model::space {
namespace {

using ::testing::HasSubstr;

TEST(NormalTail, LogCdfAgreesWithErfcAndItsAsymptote) {
  // Where erfc is still representable both forms hold; 1e-12 relative is the round-off of erfc.
  for (double x : {3.0, 0.0, -1.0, -4.99, -5.01, -6.0, -10.0, -20.0, -30.0})
    EXPECT_NEAR(log_normal_cdf(x), std::log(0.5 * std::erfc(-x / std::sqrt(2.0))),
                1e-12 * std::abs(std::log(0.5 * std::erfc(-x / std::sqrt(2.0)))))
        << x;
  // Far beyond (erfc underflows at −38): log Φ(x) = −x²/2 − log(−x) − log √(2π) + log(1 − 1/x² +
  // 3/x⁴ − …).
  for (double x : {-50.0, -1e3}) {
    const double series = -0.5 * x * x - std::log(-x) - 0.5 * std::log(2 * M_PI) +
                          std::log(1 - 1 / (x * x) + 3 / std::pow(x, 4) - 15 / std::pow(x, 6));
    EXPECT_NEAR(log_normal_cdf(x), series, 1e-12 * std::abs(series)) << x;
  }
}

TEST(NormalTail, BothSidesAtOnceAgreeWithEachSideAlone) {
  // 1 − Φ(−t) for the larger side loses at most an ulp of it; the tail forms are the same calls.
  for (double x : {0.0, 0.3, -0.3, 2.0, -2.0, 4.99, -4.99, 5.01, -5.01, 12.0, -40.0}) {
    const NormalSides s = normal_sides(x);
    EXPECT_NEAR(s.log_cdf, log_normal_cdf(x), 1e-15 + 1e-14 * std::abs(log_normal_cdf(x))) << x;
    EXPECT_NEAR(s.log_cdf_negative, log_normal_cdf(-x),
                1e-15 + 1e-14 * std::abs(log_normal_cdf(-x)))
        << x;
    EXPECT_NEAR(s.pdf_over_cdf, normal_pdf_over_cdf(x),
                1e-14 * std::max(1.0, normal_pdf_over_cdf(x)))
        << x;
    EXPECT_NEAR(s.pdf_over_cdf_negative, normal_pdf_over_cdf(-x),
                1e-14 * std::max(1.0, normal_pdf_over_cdf(-x)))
        << x;
  }
}

TEST(NormalTail, PdfOverCdfIsTheDerivativeOfLogCdf) {
  for (double x : {2.0, 0.3, -3.0, -4.9999, -5.0001, -8.0, -40.0, -500.0}) {
    const double h = 1e-5 * std::max(1.0, std::abs(x));
    const double numeric = (log_normal_cdf(x + h) - log_normal_cdf(x - h)) / (2 * h);
    // Central differences: error O(h²·f''') ≈ 1e-9 relative at these h.
    EXPECT_NEAR(normal_pdf_over_cdf(x), numeric, 1e-7 * std::max(1.0, std::abs(numeric))) << x;
  }
}

using testing::random_problem;

TEST(SpaceObjective, AnalyticGradientMatchesFiniteDifferences) {
  for (double lambda : {0.0, 3.0}) {
    SpaceProblem p = random_problem(8, 2, lambda, 5);
    p.prior_sd = lambda > 0 ? 1.5 : 0.0;  // the prior's term checked alongside the correlation's
    std::mt19937 generator(9);
    std::normal_distribution<double> normal;
    Eigen::MatrixXd q(2, 8);
    for (Eigen::Index i = 0; i < q.size(); ++i) q.data()[i] = normal(generator);
    Eigen::MatrixXd gradient;
    objective(p, q, &gradient);
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      Eigen::MatrixXd plus = q, minus = q;
      const double h = 1e-6;
      plus.data()[i] += h, minus.data()[i] -= h;
      const double numeric = (objective(p, plus, nullptr) - objective(p, minus, nullptr)) / (2 * h);
      // Central differences on a smooth function of O(100): truncation ~h²·f''' and round-off
      // ~1e-16·f/h ≈ 1e-8; 1e-6 relative leaves room for both and catches any missed term.
      EXPECT_NEAR(gradient.data()[i], numeric, 1e-6 * std::max(1.0, std::abs(numeric)))
          << "lambda " << lambda << ", coordinate " << i;
    }
  }
}

TEST(SpaceObjective, OneUnitOfDistanceIsSeventyFivePercent) {
  Eigen::MatrixXd q(1, 3);
  q << 0.0, 1.0, 2.0;  // a at distance 1 from the reference, b at distance 2
  EXPECT_NEAR(probability_first(JudgmentModel{}, q, 0, 1, 2),
              0.5 * std::erfc(-(2.0 / 3.0) / std::sqrt(2.0)), 1e-15);
  EXPECT_NEAR(probability_first(JudgmentModel{}, q, 0, 1, 2), 0.7475, 1e-4);
}

TEST(SpaceObjective, BadProblemsNameWhatIsWrong) {
  SpaceProblem p = random_problem(6, 2, 1.0, 1);
  p.triplets[3].a = 9;
  EXPECT_THAT([&] { validate(p); }, ::testing::ThrowsMessage<std::invalid_argument>(
                                        HasSubstr("triplet 3: stimulus index out of range")));
  p = random_problem(6, 2, 1.0, 1);
  p.triplets[2].a = p.triplets[2].reference;
  EXPECT_THAT([&] { validate(p); }, ::testing::ThrowsMessage<std::invalid_argument>(
                                        HasSubstr("triplet 2: the reference and both candidates")));
  p = random_problem(6, 2, 1.0, 1);
  p.triplets[0].count_b = -1;
  EXPECT_THAT([&] { validate(p); }, ::testing::ThrowsMessage<std::invalid_argument>(
                                        HasSubstr("triplet 0: negative count")));
  p = random_problem(6, 2, 1.0, 1);
  p.descriptors.conservativeResize(5, 2);
  EXPECT_THAT([&] { validate(p); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("one row per stimulus")));
  p = random_problem(6, 2, 1.0, 1);
  p.dims = 6;
  EXPECT_THAT([&] { validate(p); }, ::testing::ThrowsMessage<std::invalid_argument>(
                                        HasSubstr("needs at least 7 stimuli")));
}

}  // namespace
}  // namespace nibrig::model::space
