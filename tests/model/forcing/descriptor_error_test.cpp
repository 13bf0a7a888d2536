// The descriptor error of a prediction: closed forms (a spectrum off by a constant factor c is off
// by log10 c in its weighted mean, an amplitude descriptor, and by 2·log10 c in every band energy,
// a power), and on leave-one-out: exact data give no error, noisy data the error the summary says.
#include "model/forcing/descriptor_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "model/forcing/leave_one_out.hpp"
#include "tests/model/forcing/synthetic_exemplars.hpp"

namespace nibrig::model::forcing {
namespace {

measure::ThresholdCurve test_threshold() {
  return measure::ThresholdCurve({10.0, 1000.0}, {0.01, 0.1}, "test threshold");
}

io::VelocitySpectrum scaled(io::VelocitySpectrum spectrum, double factor) {
  for (auto& row : spectrum.amplitude_m_s2)
    for (double& a : row) a *= factor;
  return spectrum;
}

TEST(DescriptorError, AConstantFactorIsItsLogInTheMeanAndTwiceItInEveryBand) {
  const auto truth = test::make_synthetic_truth(3);
  const io::VelocitySpectrum& measured = truth.exemplars.front().measured;
  const auto threshold = test_threshold();
  for (double c : {1.0, 1.3, 0.5}) {
    const DescriptorError e = descriptor_error("t", "s", scaled(measured, c), measured, threshold);
    EXPECT_NEAR(e.log10_weighted_mean, std::log10(c), 1e-12) << c;
    ASSERT_EQ(e.log10_band_energies.size(), 4u);  // 2, 3, 4 and 5 bands
    for (int k = kMinDescriptorBands; k <= kMaxDescriptorBands; ++k) {
      ASSERT_EQ(e.log10_band_energies.at(k).size(), static_cast<std::size_t>(k));
      for (double b : e.log10_band_energies.at(k)) EXPECT_NEAR(b, 2 * std::log10(c), 1e-12) << c;
    }
  }
}

TEST(DescriptorError, PercentOffIsTheRatioLessOne) {
  EXPECT_NEAR(percent_off(std::log10(1.1)), 10.0, 1e-12);
  EXPECT_NEAR(percent_off(std::log10(0.75)), -25.0, 1e-12);
  EXPECT_EQ(percent_off(0.0), 0.0);
}

TEST(DescriptorError, ASilentSpectrumHasNoLogarithmAndIsNamed) {
  const auto truth = test::make_synthetic_truth(3);
  const io::VelocitySpectrum& measured = truth.exemplars.front().measured;
  try {
    descriptor_error("vero2", "glass", scaled(measured, 0.0), measured, test_threshold());
    ADD_FAILURE() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("vero2 on glass"), std::string::npos) << e.what();
  }
}

TEST(DescriptorError, LeaveOneOutOfExactDataPredictsTheDescriptorsExactly) {
  const auto truth = test::make_synthetic_truth(13);
  const auto threshold = test_threshold();
  const auto errors = held_out_descriptor_errors(truth.exemplars, threshold);
  std::vector<std::size_t> every(truth.exemplars.size());
  std::iota(every.begin(), every.end(), std::size_t{0});
  const auto loo = leave_one_out(truth.exemplars, every);  // without a threshold: no descriptors
  EXPECT_EQ(errors.size(), loo.summary.predicted);
  for (const auto& r : loo.results) EXPECT_FALSE(r.descriptor_error.has_value());
  for (const auto& e : errors) {
    EXPECT_NEAR(e.log10_weighted_mean, 0.0, 1e-8) << e.tool << " on " << e.surface;
    for (const auto& [k, bands] : e.log10_band_energies)
      for (double b : bands) EXPECT_NEAR(b, 0.0, 1e-8) << e.tool << " on " << e.surface;
  }
}

TEST(DescriptorError, TheSummaryIsTheRmsOfTheHeldOutErrors) {
  auto truth = test::make_synthetic_truth(13);
  test::add_log_noise(truth.exemplars, 0.2, 5);
  const auto threshold = test_threshold();
  std::vector<std::size_t> every(truth.exemplars.size());
  std::iota(every.begin(), every.end(), std::size_t{0});
  const auto loo = leave_one_out(truth.exemplars, every, {}, &threshold);
  double squares = 0.0;
  std::size_t n = 0;
  for (const auto& r : loo.results) {
    ASSERT_EQ(r.descriptor_error.has_value(), r.predictable) << r.tool;
    if (!r.descriptor_error) continue;
    // Recomputed from the prediction and the measurement, independently of the summary.
    squares += r.descriptor_error->log10_weighted_mean * r.descriptor_error->log10_weighted_mean;
    ++n;
  }
  ASSERT_GT(n, 0u);
  const double rms = std::sqrt(squares / static_cast<double>(n));
  EXPECT_GT(rms, 1e-3) << "noise of 0.2 in ln amplitude must leave an error";
  EXPECT_NEAR(loo.summary.weighted_mean_rms_log10, rms, 1e-15);
}

TEST(DescriptorError, TheSummaryIsTheRmsOverExemplarsAndTheWorstByMagnitude) {
  // Hand-made errors: weighted means 0.1, -0.3, 0.2; five band energies each, all ±0.1 or 0.
  std::vector<DescriptorError> errors(3);
  const double means[] = {0.1, -0.3, 0.2};
  for (int i = 0; i < 3; ++i) {
    errors[i].tool = "t" + std::to_string(i);
    errors[i].log10_weighted_mean = means[i];
    errors[i].log10_band_energies[kMaxDescriptorBands] = {0.1, -0.1, 0.0, 0.1, -0.1};
  }
  const DescriptorErrorSummary s = summarize(errors);
  EXPECT_EQ(s.errors, 3u);
  EXPECT_NEAR(s.rms_log10_weighted_mean, std::sqrt((0.01 + 0.09 + 0.04) / 3), 1e-15);
  EXPECT_NEAR(s.rms_log10_band_energy, std::sqrt(4 * 0.01 / 5), 1e-15);  // 12 of 15 are ±0.1
  ASSERT_NE(s.worst, nullptr);
  EXPECT_EQ(s.worst->tool, "t1");  // |-0.3| is the largest
  EXPECT_EQ(summarize(std::vector<DescriptorError>{}).worst, nullptr);
}

}  // namespace
}  // namespace nibrig::model::forcing
