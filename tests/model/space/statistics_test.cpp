#include "model/space/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace nibrig::model::space {
namespace {

TEST(SpaceStatistics, AgreementTestReproducesThePapersNewToolResult) {
  // Sec. 6.1: the prediction matched the popular opinion in 19 of 24 cases, "Z-test ... p-value
  // < 0.0022". z = (19 − 12)/√6 = 2.858, one-sided p = 0.00213.
  const AgreementTest t = agreement_test(19, 24);
  EXPECT_NEAR(t.z, 7.0 / std::sqrt(6.0), 1e-12);
  EXPECT_NEAR(t.p_value, 0.00213, 0.00001);  // normal table value, 5 digits
  EXPECT_LT(t.p_value, 0.0022);
  EXPECT_NEAR(agreement_test(12, 24).p_value, 0.5, 1e-12);  // exactly chance
}

TEST(SpaceStatistics, PearsonMatchesAHandComputation) {
  // x = 1..5, y = 2, 4, 5, 4, 5: Sxy = 6, Sxx = 10, Syy = 6 → r = 6/√60 = 0.7746; t = r√(3/(1−r²))
  // = 2.121 with 3 degrees of freedom, two-sided p = 0.1240 (Student t table).
  const Correlation c = pearson({1, 2, 3, 4, 5}, {2, 4, 5, 4, 5});
  EXPECT_NEAR(c.r, 6.0 / std::sqrt(60.0), 1e-12);
  EXPECT_NEAR(c.p_value, 0.1240, 0.0005);
  EXPECT_EQ(c.n, 5u);
  EXPECT_NEAR(pearson({1, 2, 3}, {3, 2, 1}).r, -1.0, 1e-12);
}

TEST(SpaceStatistics, SpearmanUsesMeanRanksForTies) {
  // Monotone but non-linear: ranks agree exactly.
  EXPECT_NEAR(spearman({1, 2, 3, 4}, {1, 8, 27, 64}).r, 1.0, 1e-12);
  // y ties at positions 2 and 3 (ranks 2.5, 2.5): ranks x = 1,2,3,4, y = 1,2.5,2.5,4 → r = 0.9487.
  EXPECT_NEAR(spearman({1, 2, 3, 4}, {1, 5, 5, 9}).r, 4.5 / std::sqrt(5.0 * 4.5), 1e-12);
}

TEST(SpaceStatistics, RejectsWhatHasNoCorrelation) {
  EXPECT_THROW(pearson({1, 2}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(pearson({1, 2, 3}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(pearson({1, 1, 1}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(agreement_test(5, 4), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::space
