// The prediction file written and read back: a predicted tool made of a real catalog spectrum (the
// crayon on office paper, from the paper's recordings) with a descriptor error, written as `nibrig
// predict` and the panel's Save design write it, comes back as the same design, surface, spectrum,
// μ and covariance; a file that is not a prediction or whose covariance is not symmetric is
// refused naming the file and the field.
#include "model/design/prediction_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

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

// Issue 46: fields no reader used were never checked, so a damaged file reached `space embed
// --predicted` and `export`. Each field prediction_json writes, damaged as a hand edit or a bad
// disk would (a number as a string, null, 1e300, an array), is refused by both readers, naming the
// file and the field.
TEST(PredictionFileDamage, EveryFieldIsCheckedReadOrNot) {
  const auto [tool, threshold] = crayon_as_a_prediction();
  const auto dir = nibrig::test::scratch_dir("prediction_file_damage");
  const nlohmann::json good = prediction_json(tool, threshold.source());
  // The JSON pointer of each field and the name the message gives it.
  const std::vector<std::pair<std::string, std::string>> fields = {
      {"/kind", "'kind'"},
      {"/tool", "'tool'"},
      {"/surface", "'surface'"},
      {"/mu", "'mu'"},
      {"/frequencies_hz", "'frequencies_hz'"},
      {"/speeds_mm_s/0", "'speeds_mm_s[0]'"},
      {"/amplitude_m_s2/0/0", "'amplitude_m_s2[0][0]'"},
      {"/descriptors", "'descriptors'"},
      {"/descriptors/weighted_mean", "'descriptors.weighted_mean'"},
      {"/descriptors/weighted_power", "'descriptors.weighted_power'"},
      {"/descriptors/band_energies/3/0", "'descriptors.band_energies.3[0]'"},
      {"/threshold_curve", "'threshold_curve'"},
      {"/design", "'design'"},
      {"/design/name", "'design.name'"},
      {"/design/first_mode_hz", "'design.first_mode_hz'"},
      {"/design/tip_diameter_mm", "'design.tip_diameter_mm'"},
      {"/design/mix/DM85", "'design.mix.DM85'"},
      {"/notes/0", "'notes[0]'"},
      {"/descriptor_error_covariance/names/0", "'descriptor_error_covariance.names[0]'"},
      {"/descriptor_error_covariance/matrix/0/0", "'descriptor_error_covariance.matrix[0][0]'"},
      {"/descriptor_error_covariance/vibration_samples", "'descriptor_error_covariance.vibration_samples'"},
  };
  const std::vector<std::pair<std::string, nlohmann::json>> damages = {
      {"string", "0.5"}, {"null", nullptr}, {"huge", 1e300}, {"array", nlohmann::json::array()}};
  int refused = 0;
  for (const auto& [pointer, name] : fields) {
    ASSERT_TRUE(good.contains(nlohmann::json::json_pointer(pointer))) << pointer << ": not written";
    for (const auto& [damage, value] : damages) {
      // A string where a string belongs is no damage; nor an array where one does.
      const auto& original = good.at(nlohmann::json::json_pointer(pointer));
      if ((original.is_string() && value.is_string()) || (original.is_array() && value.is_array())) continue;
      nlohmann::json j = good;
      j[nlohmann::json::json_pointer(pointer)] = value;
      const auto file = dir / ("damaged-" + damage + ".json");
      io::write_file_atomically(file, j.dump());
      for (const bool whole : {true, false}) {
        try {
          if (whole)
            read_prediction(file, threshold);
          else
            read_predicted_design(file);
          ADD_FAILURE() << pointer << " = " << value.dump() << " was taken by "
                        << (whole ? "read_prediction" : "read_predicted_design");
        } catch (const io::FormatError& e) {
          ++refused;
          EXPECT_THAT(e.what(), HasSubstr(file.filename().string())) << pointer;
          EXPECT_THAT(e.what(), HasSubstr(name)) << pointer << " = " << value.dump();
        }
      }
    }
  }
  // 7 string fields × 3 damages, 1 array × 3, 13 others × 4: 76 damaged files, each read twice.
  EXPECT_EQ(refused, 152);
}

// Values of the right type outside their range, and a design that contradicts its tool.
TEST(PredictionFileDamage, ValuesOutsideTheirRangeAreRefusedSayingWhatWasExpected) {
  const Made made = crayon_as_a_prediction();  // named, not bound: clang 14's lambdas cannot capture a binding
  const PredictedTool& tool = made.tool;
  const measure::ThresholdCurve& threshold = made.threshold;
  const auto dir = nibrig::test::scratch_dir("prediction_file_range");
  const nlohmann::json good = prediction_json(tool, threshold.source());
  const std::vector<std::tuple<std::string, nlohmann::json, std::string>> cases = {
      {"/mu", 12.0, "expected 0 to 10"},
      {"/mu", -0.1, "expected 0 to 10"},
      {"/descriptors/weighted_power", -1.0, "expected 0 to"},
      {"/design/first_mode_hz", 2e6, "expected 0 to 1e+06"},
      {"/design/tip_diameter_mm", 2.0, "expected the tool's tip, 3 mm"},
      {"/design/mix/DM85", 0.5, "expected the tool's share of DM85, 0.25"},
      {"/speeds_mm_s/0", 0.0, "above 0"},
      {"/surface", "", "expected a surface id"},
  };
  for (const auto& [pointer, value, expected] : cases) {
    nlohmann::json j = good;
    j[nlohmann::json::json_pointer(pointer)] = value;
    const auto file = dir / "range.json";
    io::write_file_atomically(file, j.dump());
    EXPECT_THAT([&] { read_predicted_design(file); },
                ::testing::ThrowsMessage<io::FormatError>(HasSubstr(expected)))
        << pointer << " = " << value.dump();
  }
  // A comparison (predict --against) is checked too when there is one.
  nlohmann::json j = good;
  j["comparison"] = {{"against", "cryon/office"}, {"rms_db", 2.5}, {"rms_db_by_speed", {2.0, 3.0}},
                     {"no_interpolation_baselines", nlohmann::json::array()}, {"beats_every_baseline", true}};
  io::write_file_atomically(dir / "compared.json", j.dump());
  EXPECT_NO_THROW(read_prediction(dir / "compared.json", threshold));
  j["comparison"]["beats_every_baseline"] = "yes";
  io::write_file_atomically(dir / "compared.json", j.dump());
  EXPECT_THAT([&] { read_prediction(dir / "compared.json", threshold); },
              ::testing::ThrowsMessage<io::FormatError>(HasSubstr("'comparison.beats_every_baseline'")));
}

}  // namespace
}  // namespace nibrig::model::design
