// forcing.json: what is written is read back unchanged, and a damaged file is refused with the
// file and the field named.
#include "model/forcing/forcing_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/io/format_error.hpp"
#include "tests/model/forcing/synthetic_exemplars.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::forcing {
namespace {

ForcingModel fitted_model() {
  auto truth = test::make_synthetic_truth(8);
  test::add_log_noise(truth.exemplars, 0.1, 1);
  ForcingModel model = fit_forcing_model(truth.exemplars);
  model.notes = {"synthetic", "second note"};
  model.held_out_descriptor_errors = held_out_descriptor_errors(
      truth.exemplars, measure::ThresholdCurve({10.0, 1000.0}, {0.01, 0.1}, "test threshold"));
  model.descriptor_error_threshold = "test threshold";
  return model;
}

TEST(ForcingFile, RoundTripKeepsEveryNumber) {
  const auto dir = nibrig::test::scratch_dir("forcing_file_round_trip");
  const ForcingModel model = fitted_model();
  write_forcing_model(dir / "forcing.json", model);
  const ForcingModel back = read_forcing_model(dir / "forcing.json");
  // nlohmann writes doubles with round-trip precision; only the mm <-> m conversions round.
  EXPECT_EQ(back.knot_frequencies_hz, model.knot_frequencies_hz);
  ASSERT_EQ(back.tip_log_gain.size(), model.tip_log_gain.size());
  for (const auto& [d, curve] : model.tip_log_gain) EXPECT_EQ(back.tip_curve(d), curve);
  EXPECT_EQ(back.material_log_gain, model.material_log_gain);
  EXPECT_NEAR(back.reference_tip_diameter_m, model.reference_tip_diameter_m, 1e-15);
  EXPECT_EQ(back.reference_material, model.reference_material);
  EXPECT_EQ(back.frequencies_hz, model.frequencies_hz);
  ASSERT_EQ(back.speeds_m_s.size(), model.speeds_m_s.size());
  for (std::size_t s = 0; s < model.speeds_m_s.size(); ++s)
    EXPECT_NEAR(back.speeds_m_s[s], model.speeds_m_s[s], 1e-15);
  EXPECT_EQ(back.surface_forcing, model.surface_forcing);
  EXPECT_EQ(back.residual_rms_db, model.residual_rms_db);
  EXPECT_EQ(back.observations, model.observations);
  EXPECT_EQ(back.skipped_nonpositive, model.skipped_nonpositive);
  ASSERT_EQ(back.exemplar_fits.size(), model.exemplar_fits.size());
  for (std::size_t e = 0; e < model.exemplar_fits.size(); ++e) {
    EXPECT_EQ(back.exemplar_fits[e].tool, model.exemplar_fits[e].tool);
    EXPECT_EQ(back.exemplar_fits[e].surface, model.exemplar_fits[e].surface);
    EXPECT_EQ(back.exemplar_fits[e].rms_db, model.exemplar_fits[e].rms_db);
  }
  EXPECT_EQ(back.notes, model.notes);
  EXPECT_EQ(back.descriptor_error_threshold, model.descriptor_error_threshold);
  ASSERT_EQ(back.held_out_descriptor_errors.size(), model.held_out_descriptor_errors.size());
  ASSERT_FALSE(model.held_out_descriptor_errors.empty());
  for (std::size_t e = 0; e < model.held_out_descriptor_errors.size(); ++e) {
    const auto &a = model.held_out_descriptor_errors[e], &b = back.held_out_descriptor_errors[e];
    EXPECT_EQ(b.tool, a.tool);
    EXPECT_EQ(b.surface, a.surface);
    EXPECT_EQ(b.log10_weighted_mean, a.log10_weighted_mean);
    EXPECT_EQ(b.log10_band_energies, a.log10_band_energies);
  }
}

TEST(ForcingFile, TheTextIsTheFileAndReadsBackAsTheFileDoes) {
  const auto dir = nibrig::test::scratch_dir("forcing_file_text");
  const ForcingModel model = fitted_model();
  write_forcing_model(dir / "forcing.json", model);
  const std::string text = forcing_model_text(model, "kept in memory");
  std::ifstream in(dir / "forcing.json");
  EXPECT_EQ(text, std::string(std::istreambuf_iterator<char>(in), {}));
  // Read from the text, the model is the one read from the file, to the last bit.
  const ForcingModel from_text = parse_forcing_model(text, "kept in memory");
  const ForcingModel from_file = read_forcing_model(dir / "forcing.json");
  EXPECT_EQ(from_text.reference_tip_diameter_m, from_file.reference_tip_diameter_m);
  EXPECT_EQ(from_text.speeds_m_s, from_file.speeds_m_s);
  EXPECT_EQ(from_text.surface_forcing, from_file.surface_forcing);
  EXPECT_EQ(from_text.material_log_gain, from_file.material_log_gain);
  EXPECT_EQ(forcing_model_text(from_text, "again"), forcing_model_text(from_file, "again"));
  // A damaged text is refused naming what it is in place of a file.
  try {
    parse_forcing_model("{\"format\": \"nibrig-forcing\", \"version\": 1}", "a pickled designer");
    FAIL() << "a text without knots was read";
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("a pickled designer"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("knot_frequencies_hz"), std::string::npos) << e.what();
  }
}

TEST(ForcingFile, AFileWithoutDescriptorErrorsReadsWithNone) {
  // Files written before the held-out descriptor errors existed.
  const auto dir = nibrig::test::scratch_dir("forcing_file_old");
  ForcingModel model = fitted_model();
  model.held_out_descriptor_errors.clear();
  write_forcing_model(dir / "forcing.json", model);
  std::ifstream in(dir / "forcing.json");
  EXPECT_FALSE(nlohmann::json::parse(in).contains("held_out_descriptor_errors"));
  EXPECT_TRUE(read_forcing_model(dir / "forcing.json").held_out_descriptor_errors.empty());
}

// A calibrated material's per-knot errors and a calibrated surface's per-cell errors are written
// and read back; a model without them (every file before calibrations existed) writes no such
// field and reads with none.
ForcingModel with_calibration_errors(ForcingModel model) {
  model.material_log_gain_se["DM95"] = std::vector<double>(model.knot_frequencies_hz.size(), 0.0);
  for (std::size_t k = 0; k < model.knot_frequencies_hz.size(); ++k)
    model.material_log_gain_se["DM95"][k] = 0.01 * static_cast<double>(k + 1);
  auto& surface = model.surface_log_forcing_se[model.surface_forcing.begin()->first];
  for (std::size_t s = 0; s < model.speeds_m_s.size(); ++s)
    surface.push_back(std::vector<double>(model.frequencies_hz.size(), 0.05 + 0.01 * s));
  return model;
}

TEST(ForcingFile, CalibrationErrorsRoundTripAndAreOptional) {
  const auto dir = nibrig::test::scratch_dir("forcing_file_calibration_errors");
  const ForcingModel model = with_calibration_errors(fitted_model());
  write_forcing_model(dir / "calibrated.json", model);
  const ForcingModel back = read_forcing_model(dir / "calibrated.json");
  EXPECT_EQ(back.material_log_gain_se, model.material_log_gain_se);
  EXPECT_EQ(back.surface_log_forcing_se, model.surface_log_forcing_se);
  // At a knot the error is the knot's own; a prediction's adds the surface's in quadrature.
  const std::string surface = model.surface_forcing.begin()->first;
  EXPECT_NEAR(back.material_log_gain_se_at("DM95", back.knot_frequencies_hz[3]), 0.04, 1e-12);
  const std::size_t bin = 0;
  const double material_se = back.material_log_gain_se_at("DM95", back.frequencies_hz[bin]);
  EXPECT_NEAR(back.prediction_log_se(surface, "DM95", 1, bin), std::hypot(material_se, 0.06),
              1e-12);
  EXPECT_EQ(back.prediction_log_se(surface, "vero", 0, bin), 0.05);  // vero: fitted, no SE stored

  write_forcing_model(dir / "plain.json", fitted_model());
  std::ifstream in(dir / "plain.json");
  const auto json = nlohmann::json::parse(in);
  EXPECT_FALSE(json["material_curves"][0].contains("log_gain_se"));
  EXPECT_FALSE(json["surfaces"][0].contains("log_forcing_se"));
  const ForcingModel plain = read_forcing_model(dir / "plain.json");
  EXPECT_TRUE(plain.material_log_gain_se.empty());
  EXPECT_TRUE(plain.surface_log_forcing_se.empty());
  EXPECT_EQ(plain.prediction_log_se(surface, "DM95", 0, bin), 0.0);
}

class DamagedForcingFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = nibrig::test::scratch_dir("forcing_file_damaged");
    write_forcing_model(dir_ / "good.json", fitted_model());
    std::ifstream in(dir_ / "good.json");
    good_ = nlohmann::json::parse(in);
  }

  // Writes `json` to a file and expects reading it to fail naming the file and `field`.
  void expect_refused(const nlohmann::json& json, const std::string& field,
                      const std::string& problem) {
    const auto file = dir_ / "bad.json";
    std::ofstream(file) << json.dump();
    try {
      read_forcing_model(file);
      ADD_FAILURE() << "expected a FormatError for " << field;
    } catch (const io::FormatError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(file.string()), std::string::npos) << what;
      EXPECT_NE(what.find("field '" + field + "'"), std::string::npos) << what;
      EXPECT_NE(what.find(problem), std::string::npos) << what;
    }
  }

  std::filesystem::path dir_;
  nlohmann::json good_;
};

TEST_F(DamagedForcingFile, MissingFieldIsNamed) {
  auto j = good_;
  j.erase("knot_frequencies_hz");
  expect_refused(j, "knot_frequencies_hz", "missing field");
  j = good_;
  j["surfaces"][1].erase("forcing_n");
  expect_refused(j, "surfaces[1].forcing_n", "missing field");
}

TEST_F(DamagedForcingFile, WrongLengthsAreNamed) {
  auto j = good_;
  j["tip_curves"][0]["log_gain"].erase(0);
  expect_refused(j, "tip_curves[0].log_gain", "one value per knot (11), found 10");
  j = good_;
  j["surfaces"][0]["forcing_n"][1].erase(3);
  expect_refused(j, "surfaces[0].forcing_n[1]", "one value per frequency");
  j = good_;
  j["surfaces"][2]["forcing_n"].erase(0);
  expect_refused(j, "surfaces[2].forcing_n", "one row per speed");
}

TEST_F(DamagedForcingFile, BadValuesAreNamed) {
  auto j = good_;
  j["format"] = "nibrig-space";
  expect_refused(j, "format", "nibrig-forcing");
  j = good_;
  j["knot_frequencies_hz"][4] = 10.0;
  expect_refused(j, "knot_frequencies_hz[4]", "strictly increasing");
  j = good_;
  j["surfaces"][0]["forcing_n"][0][5] = -1.0;
  expect_refused(j, "surfaces[0].forcing_n[0][5]", ">= 0");
  j = good_;
  j["material_curves"][0]["log_gain"][2] = "high";
  expect_refused(j, "material_curves[0].log_gain[2]", "expected a number");
  j = good_;
  for (auto& curve : j["material_curves"])
    if (curve["material"] == "vero") curve["log_gain"][0] = 0.5;
  expect_refused(j, "material_curves", "must be all zeros");
  j = good_;
  j["surfaces"][1]["id"] = j["surfaces"][0]["id"];
  expect_refused(j, "surfaces[1].id", "a second entry");
}

TEST_F(DamagedForcingFile, BadDescriptorErrorsAreNamed) {
  auto j = good_;
  j["held_out_descriptor_errors"]["exemplars"][1]["log10_band_energies"]["3"].erase(0);
  expect_refused(j, "held_out_descriptor_errors.exemplars[1].log10_band_energies.3",
                 "expected 3 band values, found 2");
  j = good_;
  j["held_out_descriptor_errors"]["exemplars"][0]["log10_band_energies"].erase("5");
  expect_refused(j, "held_out_descriptor_errors.exemplars[0].log10_band_energies.5",
                 "missing field");
  j = good_;
  j["held_out_descriptor_errors"]["exemplars"][0]["log10_weighted_mean"] = "loud";
  expect_refused(j, "held_out_descriptor_errors.exemplars[0].log10_weighted_mean",
                 "expected a number");
}

TEST_F(DamagedForcingFile, BadCalibrationErrorsAreNamed) {
  auto j = good_;
  j["material_curves"][1]["log_gain_se"] = std::vector<double>(10, 0.1);
  expect_refused(j, "material_curves[1].log_gain_se", "one value per knot (11), found 10");
  j = good_;
  j["material_curves"][1]["log_gain_se"] = std::vector<double>(11, -0.1);
  expect_refused(j, "material_curves[1].log_gain_se[0]", "standard error");
  j = good_;
  j["surfaces"][0]["log_forcing_se"] = nlohmann::json::array({std::vector<double>(3, 0.1)});
  expect_refused(j, "surfaces[0].log_forcing_se", "one row per speed");
  j = good_;
  const std::size_t bins = j["frequencies_hz"].size();
  j["surfaces"][0]["log_forcing_se"] =
      nlohmann::json::array({std::vector<double>(bins, 0.1), std::vector<double>(bins - 1, 0.1)});
  expect_refused(j, "surfaces[0].log_forcing_se[1]", "one value per frequency");
}

// A gain far outside what a fit reaches is refused by the reader, so that `predict` never reports an
// infinite vibration (a log_gain of 1e300 would give "weighted mean vibration inf").
TEST_F(DamagedForcingFile, AGainNoFitReachesIsNamed) {
  auto j = good_;
  j["tip_curves"][0]["log_gain"][1] = 1e300;
  expect_refused(j, "tip_curves[0].log_gain[1]", "natural-log gain");
  j = good_;
  j["tip_curves"][0]["log_gain"][1] = -51.0;
  expect_refused(j, "tip_curves[0].log_gain[1]", "natural-log gain");
}

}  // namespace
}  // namespace nibrig::model::forcing
