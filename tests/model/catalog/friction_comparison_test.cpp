// The comparison of the catalog's friction fits with the authors' recipe that `catalog build`
// prints, on analyses whose ranges, medians and differences are counted here by hand.
#include "model/catalog/friction_comparison.hpp"

#include <gtest/gtest.h>

namespace nibrig::model::catalog {
namespace {

FrictionAnalysis analysis(double fit, double upstream) {
  FrictionAnalysis a;
  a.fit.mu = fit;
  a.upstream_mu = upstream;
  return a;
}

TEST(FrictionComparison, RangesMediansAndTheMeanAbsoluteDifference) {
  const auto c = compare_with_upstream(
      {analysis(0.20, 0.25), analysis(0.10, 0.10), analysis(0.30, 0.20), analysis(0.15, 0.19)});
  EXPECT_EQ(c.fit_min, 0.10);
  EXPECT_EQ(c.fit_max, 0.30);
  EXPECT_EQ(c.fit_median, 0.20);  // the upper middle of 0.10 0.15 0.20 0.30
  EXPECT_EQ(c.upstream_min, 0.10);
  EXPECT_EQ(c.upstream_max, 0.25);
  EXPECT_EQ(c.upstream_median, 0.20);  // of 0.10 0.19 0.20 0.25
  EXPECT_NEAR(c.mean_abs_difference, (0.05 + 0.0 + 0.10 + 0.04) / 4, 1e-15);
  EXPECT_THROW(compare_with_upstream({}), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::catalog
