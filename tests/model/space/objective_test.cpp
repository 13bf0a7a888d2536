#include "model/space/objective.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "model/numeric/cpu_features.hpp"
#include "model/space/normal_tail.hpp"
#include "tests/model/space/study_fixture.hpp"

namespace nibrig::model::space {
namespace {

using ::testing::HasSubstr;

TEST(NormalTail, LogCdfAgreesWithErfcAndItsAsymptote) {
  // Where erfc is still representable both forms hold (the continued fraction from −30 on, checked
  // beyond it); 1e-12 relative is the round-off of erfc.
  for (double x : {3.0, 0.0, -1.0, -4.99, -5.01, -6.0, -10.0, -20.0, -29.99, -30.01, -35.0})
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
  // 1 − Φ(−t) for the larger side loses at most an ulp of it, and its log is taken as log(1 −
  // Φ(−t)): within 1e-15 absolute, which is what a sum of likelihoods needs; the tail forms are
  // the same calls.
  for (double x : {0.0, 0.3, -0.3, 2.0, -2.0, 4.99, -4.99, 12.0, -20.0, 29.99, -29.99, 30.01, -30.01,
                   -40.0}) {
    const NormalSides s = normal_sides(x);
    EXPECT_NEAR(s.cdf, 0.5 * std::erfc(-x / std::sqrt(2.0)), 1e-16 + 1e-14 * s.cdf) << x;
    EXPECT_NEAR(s.cdf_negative, 0.5 * std::erfc(x / std::sqrt(2.0)), 1e-16 + 1e-14 * s.cdf_negative) << x;
    // A log not asked for is not worked out; the rest is the same.
    for (const auto& [a, b] : {std::pair{false, true}, std::pair{true, false}}) {
      const NormalSides one = normal_sides(x, a, b);
      EXPECT_EQ(one.log_cdf, a ? s.log_cdf : 0.0) << x;
      EXPECT_EQ(one.log_cdf_negative, b ? s.log_cdf_negative : 0.0) << x;
      EXPECT_EQ(one.pdf_over_cdf, s.pdf_over_cdf) << x;
      EXPECT_EQ(one.pdf_over_cdf_negative, s.pdf_over_cdf_negative) << x;
    }
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

TEST(SpaceObjective, APairTableAndEachTripletsOffsetsGiveTheSameValueAndGradients) {
  // The likelihood reads a table of every pair's distances where pairs are fewer than triplet
  // sides, each triplet's own offsets otherwise. The same 60 triplets over 8 stimuli (28 pairs: the
  // table) and over the same 8 among 40 (780 pairs: the offsets), the other 32 judged in none.
  SpaceProblem few = random_problem(8, 2, 0.0, 41);
  few.descriptors.resize(0, 0);
  SpaceProblem many = few;
  many.stimuli = 40;
  std::mt19937 generator(42);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd q_many(2, 40);
  for (Eigen::Index i = 0; i < q_many.size(); ++i) q_many.data()[i] = normal(generator);
  const Eigen::MatrixXd q_few = q_many.leftCols(8);
  for (const char* family : {"logistic+lapse+noise", "student-t", "probit+noise"}) {
    JudgmentModel m_few;
    m_few.family = parse_family(family);
    m_few.lapse = m_few.family.lapse ? 0.07 : 0.0;
    JudgmentModel m_many = m_few;
    if (m_few.family.stimulus_noise) {
      m_many.log_noise = Eigen::VectorXd::Zero(40);  // the unjudged 32 at the prior's mean: no cost
      for (Eigen::Index i = 0; i < 8; ++i) m_many.log_noise(i) = 0.3 * normal(generator);
      m_few.log_noise = m_many.log_noise.head(8);
    }
    Eigen::MatrixXd g_few, g_many;
    ModelGradient mg_few, mg_many;
    const double f_few = objective(few, q_few, m_few, &g_few, &mg_few);
    const double f_many = objective(many, q_many, m_many, &g_many, &mg_many);
    // Sums of the same terms in the same order: round-off apart at most.
    EXPECT_NEAR(f_few, f_many, 1e-12 * std::abs(f_few)) << family;
    EXPECT_LT((g_few - g_many.leftCols(8)).cwiseAbs().maxCoeff(), 1e-12 * g_few.cwiseAbs().maxCoeff()) << family;
    EXPECT_EQ(g_many.rightCols(32).cwiseAbs().maxCoeff(), 0.0) << family;
    EXPECT_NEAR(mg_few.lapse, mg_many.lapse, 1e-12 * std::max(1.0, std::abs(mg_few.lapse))) << family;
    if (m_few.family.stimulus_noise) {
      EXPECT_LT((mg_few.log_noise - mg_many.log_noise.head(8)).cwiseAbs().maxCoeff(), 1e-12) << family;
      EXPECT_EQ(mg_many.log_noise.tail(32).cwiseAbs().maxCoeff(), 0.0) << family;
    }
  }
}

TEST(SpaceObjective, TheAvx2LoopsGiveThePortableLoopsBits) {
  // The AVX2 build runs the same operations in the same order without FMA, so a fit does not depend
  // on the machine's vector width: equal to the bit, for every link, with a lapse and noises, in
  // 1-3 dimensions (fixed-size columns) and 5 (dynamic), through the pair table (every triplet of
  // 12 stimuli: 660, two whole blocks and a part) and through each triplet's offsets (60 triplets
  // of 200 stimuli); a tenth of the coordinates far out puts some probit triplets in the far tail.
  if (!numeric::cpu_has_avx2_fma()) GTEST_SKIP() << "this CPU has no AVX2";
  std::mt19937 generator(77);
  std::normal_distribution<double> normal;
  for (std::size_t dims : {1u, 2u, 3u, 5u})
    for (bool table : {true, false}) {
      SpaceProblem p =
          table ? testing::every_triplet_judged(
                      testing::random_truth(static_cast<Eigen::Index>(dims), 12, 5), 3, 6)
                : random_problem(200, dims, 0.0, 7);
      p.descriptors.resize(0, 0);
      Eigen::MatrixXd q(static_cast<Eigen::Index>(dims), static_cast<Eigen::Index>(p.stimuli));
      for (Eigen::Index i = 0; i < q.size(); ++i)
        q.data()[i] = (i % 10 == 0 ? 40.0 : 1.5) * normal(generator);
      for (const char* family : {"probit", "logistic", "student-t", "probit+lapse+noise",
                                 "student-t+lapse", "logistic+noise"}) {
        JudgmentModel m;
        m.family = parse_family(family);
        m.lapse = m.family.lapse ? 0.03 : 0.0;
        if (m.family.stimulus_noise) {
          m.log_noise.resize(static_cast<Eigen::Index>(p.stimuli));
          for (Eigen::Index i = 0; i < m.log_noise.size(); ++i)
            m.log_noise(i) = 0.3 * normal(generator);
        }
        Eigen::MatrixXd g_portable, g_avx2;
        ModelGradient mg_portable, mg_avx2;
        const double f_portable =
            objective(p, q, m, &g_portable, &mg_portable, LoopBuild::portable);
        const double f_avx2 = objective(p, q, m, &g_avx2, &mg_avx2, LoopBuild::avx2);
        const std::string where = std::string(family) + ", " + std::to_string(dims) + "-D, " +
                                  (table ? "pair table" : "offsets");
        EXPECT_EQ(f_avx2, f_portable) << where;
        EXPECT_TRUE((g_avx2.array() == g_portable.array()).all()) << where;
        EXPECT_EQ(mg_avx2.lapse, mg_portable.lapse) << where;
        EXPECT_TRUE((mg_avx2.log_noise.array() == mg_portable.log_noise.array()).all()) << where;
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
