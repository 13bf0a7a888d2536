#include "model/measure/effective_sample_size.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace nibrig::model::measure {
namespace {

std::vector<double> ar1(std::size_t n, double phi, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<double> x(n);
  double v = unit(rng) / std::sqrt(1.0 - phi * phi);  // start in the stationary distribution
  for (double& xi : x) {
    xi = v;
    v = phi * v + unit(rng);
  }
  return x;
}

TEST(EffectiveSampleSize, MatchesTheAr1ClosedForm) {
  for (double phi : {0.0, 0.5, 0.9, 0.98}) {
    const auto x = ar1(400000, phi, 17);
    const auto s = summarize_autocorrelation(x);
    const double tau = (1.0 + phi) / (1.0 - phi);
    // τ is estimated from 400k samples: its relative SD is about sqrt(2(2M+1)/n) with M ≈ 5τ, i.e.
    // 2-14 %; plus the window's truncation bias (< 1 %). 20 % covers φ = 0.98 (τ = 99) at 1.5 SD.
    EXPECT_NEAR(s.integrated_time_samples / tau, 1.0, 0.2) << "phi " << phi;
    EXPECT_NEAR(s.variance, 1.0 / (1.0 - phi * phi), 0.1 / (1.0 - phi * phi)) << "phi " << phi;
    EXPECT_NEAR(s.effective_samples, 400000.0 / s.integrated_time_samples, 1e-6);
  }
}

TEST(EffectiveSampleSize, StandardErrorHasTheRightSpreadAcrossRecords) {
  // z = (mean - 0) / SE over 300 independent AR(1) records: SD(z) must be 1 (the naive SE would
  // give sqrt(τ) = 4.4). The SD of 300 z-values scatters by 1/sqrt(600) = 4 %: allow 15 %.
  double sum_sq = 0.0;
  for (unsigned seed = 0; seed < 300; ++seed) {
    const auto x = ar1(20000, 0.9, 500 + seed);
    const auto s = summarize_autocorrelation(x);
    double mean = 0.0;
    for (double v : x) mean += v / static_cast<double>(x.size());
    const double z = mean / standard_error_of_mean(s, x.size());
    sum_sq += z * z;
  }
  EXPECT_NEAR(std::sqrt(sum_sq / 300.0), 1.0, 0.15);
}

TEST(EffectiveSampleSize, HandlesConstantAndTinySeries) {
  const std::vector<double> flat(100, 3.0);
  const auto s = summarize_autocorrelation(flat);
  EXPECT_EQ(s.variance, 0.0);
  EXPECT_EQ(s.effective_samples, 100.0);
  EXPECT_EQ(standard_error_of_mean(s, 100), 0.0);
  EXPECT_THROW(summarize_autocorrelation(std::vector<double>{1.0}), std::invalid_argument);
  EXPECT_THROW(summarize_autocorrelation(std::vector<double>{1.0, NAN}), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::measure
