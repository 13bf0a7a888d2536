// The prediction file written and read back: a predicted tool made of a real catalog spectrum (the
// crayon on office paper, from the paper's recordings) with a descriptor error, written as `nibrig
// predict` and the panel's Save design write it, comes back as the same design, surface, spectrum,
// μ and covariance; a file that is not a prediction or whose covariance is not symmetric is
// refused naming the file and the field.
#include "model/design/prediction_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "model/io/atomic_file.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/format_error.hpp"
#include "model/measure/descriptors.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

using ::testing::HasSubstr;

struct Made {
  PredictedTool tool;
  measure::ThresholdCurve threshold;
};

Made crayon_as_a_prediction() {
  const auto catalog = io::read_catalog(io::default_catalog());
  auto threshold = measure::ThresholdCurve::load(io::default_threshold_curve());
  PredictedTool tool;
  for (const auto& p : catalog.pairings)
    if (p.tool == "cryon" && p.surface == "office" && p.vibration && p.friction) {
      tool.spectrum = p.vibration->spectrum;
      tool.mu = p.friction->mu;
    }
  EXPECT_FALSE(tool.spectrum.amplitude_m_s2.empty()) << "the bundled catalog lost the crayon on office paper";
  tool.point = parse_design_point("DM85:0.25,vero:0.75,tip=3mm");
  tool.surface = "office";
  tool.design_name = "printed mix";
  tool.first_mode_hz = 93.5;
  tool.vibration = measure::compute_vibration_descriptors(tool.spectrum, threshold);
  tool.descriptor_errors.names = {"mu", "log10_weighted_mean"};
  tool.descriptor_errors.covariance.resize(2, 2);
  tool.descriptor_errors.covariance << 4e-4, 1e-5, 1e-5, 2.5e-3;
  tool.descriptor_errors.vibration_samples = 12;
  tool.descriptor_errors.friction_samples = 9;
  return {std::move(tool), std::move(threshold)};
}

TEST(PredictionFile, WhatIsWrittenIsReadBack) {
  const auto [tool, threshold] = crayon_as_a_prediction();
  const auto file = nibrig::test::scratch_dir("prediction_file") / "predicted.json";
  io::write_file_atomically(file, prediction_json(tool, threshold.source()).dump());
  const auto read = read_prediction(file, threshold);
  EXPECT_EQ(to_string(read.point), to_string(tool.point));
  const auto design = read_predicted_design(file);  // what `export` takes
  EXPECT_EQ(to_string(design.point), to_string(tool.point));
  EXPECT_EQ(design.surface, tool.surface);
  EXPECT_EQ(read.surface, "office");
  ASSERT_TRUE(read.pairing.vibration.has_value());
  const auto& spectrum = read.pairing.vibration->spectrum;
  ASSERT_EQ(spectrum.amplitude_m_s2.size(), tool.spectrum.amplitude_m_s2.size());
  // JSON keeps a double's 17 significant digits: the amplitudes come back exactly; the speeds go
  // through mm/s and back (one multiplication and one division, a few ulps).
  for (std::size_t s = 0; s < spectrum.amplitude_m_s2.size(); ++s) {
    EXPECT_NEAR(spectrum.speeds_m_s[s], tool.spectrum.speeds_m_s[s], 1e-15);
    for (std::size_t j = 0; j < spectrum.amplitude_m_s2[s].size(); ++j)
      EXPECT_EQ(spectrum.amplitude_m_s2[s][j], tool.spectrum.amplitude_m_s2[s][j]);
  }
  // Its descriptors are recomputed from the spectrum with the same threshold: the same values.
  EXPECT_NEAR(read.pairing.vibration->weighted_mean, tool.vibration.weighted_mean, 1e-12 * tool.vibration.weighted_mean);
  ASSERT_TRUE(read.pairing.friction.has_value());
  EXPECT_EQ(read.pairing.friction->mu, tool.mu);
  EXPECT_EQ(read.descriptor_errors.names, tool.descriptor_errors.names);
  EXPECT_EQ(read.descriptor_errors.covariance, tool.descriptor_errors.covariance);
  EXPECT_EQ(read.descriptor_errors.vibration_samples, 12u);
  EXPECT_EQ(read.descriptor_errors.friction_samples, 9u);
}

TEST(PredictionFile, AFileThatIsNotAPredictionIsRefusedNamingTheFileAndField) {
  const auto [tool, threshold] = crayon_as_a_prediction();
  const auto dir = nibrig::test::scratch_dir("prediction_file_bad");
  auto j = prediction_json(tool, threshold.source());
  j["kind"] = "measurement";
  io::write_file_atomically(dir / "kind.json", j.dump());
  try {
    read_prediction(dir / "kind.json", threshold);
    FAIL() << "a measurement was read as a prediction";
  } catch (const io::FormatError& e) {
    EXPECT_THAT(e.what(), HasSubstr("kind.json"));
    EXPECT_THAT(e.what(), HasSubstr("kind"));
  }
  j = prediction_json(tool, threshold.source());
  j["descriptor_error_covariance"]["matrix"][0][1] = 0.5;
  io::write_file_atomically(dir / "asymmetric.json", j.dump());
  try {
    read_prediction(dir / "asymmetric.json", threshold);
    FAIL() << "an asymmetric covariance was taken";
  } catch (const io::FormatError& e) {
    EXPECT_THAT(e.what(), HasSubstr("asymmetric.json"));
    EXPECT_THAT(e.what(), HasSubstr("symmetric"));
  }
  j = prediction_json(tool, threshold.source());
  j["tool"] = "DM85:0.7,vero:0.7,tip=3mm";
  io::write_file_atomically(dir / "mix.json", j.dump());
  EXPECT_THROW(read_prediction(dir / "mix.json", threshold), io::FormatError);
  EXPECT_THROW(read_predicted_design(dir / "mix.json"), io::FormatError);
  EXPECT_THROW(read_predicted_design(dir / "kind.json"), io::FormatError);
}

}  // namespace
}  // namespace nibrig::model::design
