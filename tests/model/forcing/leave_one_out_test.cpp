// Leave-one-out on synthetic data: exact data are predicted exactly, what cannot be predicted is
// said with its reason, and the error measure is the dB RMS it claims to be.
#include "model/forcing/leave_one_out.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/model/forcing/synthetic_exemplars.hpp"

namespace nibrig::model::forcing {
namespace {

using test::add_log_noise;
using test::make_synthetic_truth;

std::vector<std::size_t> all_of(const std::vector<ForcingExemplar>& exemplars) {
  std::vector<std::size_t> indices(exemplars.size());
  for (std::size_t k = 0; k < indices.size(); ++k) indices[k] = k;
  return indices;
}

TEST(LeaveOneOut, NoiseFreeDataArePredictedExactly) {
  const auto truth = make_synthetic_truth(13);
  const auto loo = leave_one_out(truth.exemplars, all_of(truth.exemplars));
  ASSERT_EQ(loo.results.size(), truth.exemplars.size());
  std::size_t predicted = 0;
  for (const auto& r : loo.results) {
    if (!r.predictable) continue;
    ++predicted;
    // The training data still come from the true model and still determine it.
    EXPECT_LT(r.rms_db, 1e-7) << r.tool << " on " << r.surface;
    ASSERT_EQ(r.rms_db_by_speed.size(), 2u);
    EXPECT_EQ(r.training_exemplars, truth.exemplars.size() - 1);
    EXPECT_GT(r.baseline_rms_db, 0.1) << "tools differ, so a surface mean must miss";
  }
  EXPECT_EQ(predicted, loo.summary.predicted);
  EXPECT_EQ(loo.summary.predicted + loo.summary.not_predictable, truth.exemplars.size());
}

TEST(LeaveOneOut, SaysWhyAnExemplarCannotBePredicted) {
  auto truth = make_synthetic_truth();
  ForcingExemplar alone = truth.exemplars.front();
  alone.tool = "vero2";
  alone.surface = "d";  // the only tool on surface d
  alone.tip_diameter_m = 0.002;
  alone.material = "vero";
  truth.exemplars.push_back(alone);
  ForcingExemplar teflon = truth.exemplars.front();  // the only teflon tool, on surface a
  teflon.tool = "teflon1";
  teflon.material = "teflon";
  truth.exemplars.push_back(teflon);
  const std::vector<std::size_t> held{truth.exemplars.size() - 2, truth.exemplars.size() - 1, 0};
  const auto loo = leave_one_out(truth.exemplars, held);
  ASSERT_EQ(loo.results.size(), 3u);
  EXPECT_FALSE(loo.results[0].predictable);
  EXPECT_NE(loo.results[0].reason.find("no other tool was measured on d"), std::string::npos)
      << loo.results[0].reason;
  EXPECT_FALSE(loo.results[1].predictable);
  EXPECT_NE(loo.results[1].reason.find("material 'teflon'"), std::string::npos)
      << loo.results[1].reason;
  EXPECT_TRUE(loo.results[2].predictable);
  EXPECT_EQ(loo.summary.not_predictable, 2u);
  ASSERT_EQ(loo.summary.worst.size(), 1u);
  EXPECT_EQ(loo.summary.worst[0], 2u);
  EXPECT_THROW(leave_one_out(truth.exemplars, std::vector<std::size_t>{999}),
               std::invalid_argument);
}

TEST(LeaveOneOut, SummaryOrdersTheWorstAndAgreesWithTheResults) {
  auto truth = make_synthetic_truth(3);
  add_log_noise(truth.exemplars, 0.25, 17);
  const auto loo = leave_one_out(truth.exemplars, all_of(truth.exemplars));
  std::vector<double> errors;
  for (const auto& r : loo.results)
    if (r.predictable) errors.push_back(r.rms_db);
  ASSERT_EQ(loo.summary.worst.size(), 3u);
  std::sort(errors.rbegin(), errors.rend());
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_DOUBLE_EQ(loo.results[loo.summary.worst[k]].rms_db, errors[k]);
  EXPECT_DOUBLE_EQ(loo.summary.max_rms_db, errors.front());
  double mean = 0;
  for (double e : errors) mean += e / static_cast<double>(errors.size());
  EXPECT_NEAR(loo.summary.mean_rms_db, mean, 1e-12);
  // Held-out noise of σ = 0.25 (2.2 dB) is the floor of every prediction; the estimate of the
  // training's F, t, m adds to it.
  EXPECT_GT(loo.summary.median_rms_db, 0.9 * 20 / std::log(10.0) * 0.25);
}

TEST(LeaveOneOut, ASubsetOfEveryExemplarHeldOutIsThatSubsetHeldOut) {
  // Each hold-out trains on all the others whichever set it belongs to, so the paper's tools (or
  // any subset) summarised from a leave-every-one-out equal a leave-one-out of that subset.
  auto truth = make_synthetic_truth(3);
  add_log_noise(truth.exemplars, 0.25, 17);
  const std::vector<std::size_t> subset{0, 2, 3, 7, 11};
  const auto direct = leave_one_out(truth.exemplars, subset);
  const auto every = leave_every_one_out(truth.exemplars);
  ASSERT_EQ(every.results.size(), truth.exemplars.size());
  std::vector<HeldOutResult> picked;
  for (std::size_t k : subset) picked.push_back(every.results[k]);
  const auto summary = summarize(picked);
  EXPECT_EQ(summary.predicted, direct.summary.predicted);
  EXPECT_DOUBLE_EQ(summary.mean_rms_db, direct.summary.mean_rms_db);
  EXPECT_DOUBLE_EQ(summary.median_rms_db, direct.summary.median_rms_db);
  EXPECT_EQ(summary.worst, direct.summary.worst);
}

TEST(LeaveOneOut, SpectrumErrorIsTheRmsOfDecibelDifferences) {
  io::VelocitySpectrum measured{{10, 20}, {0.1, 0.2}, {{1.0, 2.0}, {1.0, 1.0}}};
  io::VelocitySpectrum predicted{{10, 20}, {0.1, 0.2}, {{10.0, 2.0}, {0.0, 0.1}}};
  const auto error = log_spectrum_error(predicted, measured);
  // Speed 0: +20 dB and 0 dB; speed 1: a zero prediction is left out, then −20 dB.
  ASSERT_EQ(error.rms_db_by_speed.size(), 2u);
  EXPECT_NEAR(error.rms_db_by_speed[0], std::sqrt((400.0 + 0.0) / 2), 1e-12);
  EXPECT_NEAR(error.rms_db_by_speed[1], 20.0, 1e-12);
  EXPECT_NEAR(error.rms_db, std::sqrt((400.0 + 0.0 + 400.0) / 3), 1e-12);
  predicted.amplitude_m_s2[1].pop_back();
  EXPECT_THROW(log_spectrum_error(predicted, measured), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::forcing
