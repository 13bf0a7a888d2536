#include "model/io/catalog_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

VelocitySpectrum spectrum() {
  VelocitySpectrum s;
  s.frequencies_hz = {6.0, 50.0, 100.0, 250.0};
  s.speeds_m_s = {0.017, 0.056, 0.25};
  s.amplitude_m_s2 = {{0.01, 0.02, 0.03, 0.005}, {0.02, 0.04, 0.05, 0.01}, {0.1, 0.2, 0.3, 0.4}};
  return s;
}

Catalog sample_catalog() {
  Catalog c;
  c.citation =
      "M. Piovarci et al., Perception-Aware Modeling and Fabrication of Digital Drawing Tools, ACM "
      "TOG 37(4), 2018";
  c.tools = {{"p2h", "2H pencil", "real", "", std::nullopt},
             {"vero1", "VeroClear, 1 mm tip", "printed", "vero", 1e-3},
             {"design_a", "interpolated design", "predicted", "DM85", 2.5e-3}};
  c.surfaces = {{"office", "80 g office paper"}, {"glass", "glass"}};
  FrictionDescriptor f;
  f.mu = 0.21;
  f.mu_ci_low = 0.19;
  f.mu_ci_high = 0.23;
  f.samples = 31885;
  f.speeds_m_s = {0.05, 0.15, 0.25};
  f.mu_by_speed = {0.2, 0.21, 0.22};
  f.provenance = {"piovarci2018/friction/real_tools/p2h_office_2.2N_14_1.csv.gz",
                  "Coulomb fit over contact"};
  VibrationDescriptor v;
  v.spectrum = spectrum();
  v.weighted_mean = 1.25;
  v.weighted_power = 3.5;
  v.band_energies = {{1, {2.0}}, {3, {0.5, 1.0, 0.25}}};
  v.threshold_curve = "assets/threshold_curve.csv";
  v.provenance = {"piovarci2018/vibration/arm2/arm_stab_office.csv.gz", "velocity-binned spectrum"};
  c.pairings = {{"p2h", "office", f, v},
                {"vero1", "glass", std::nullopt, v},
                {"design_a", "glass", f, std::nullopt}};
  c.notes = {"vibration/prints/ts.csv.gz skipped: not a recording"};
  return c;
}

// Speeds are stored in mm/s and converted back: one multiplication and one division by 1000 each
// cost at most an ulp or two, hence 1e-12 relative.
void expect_near_all(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-12 * std::abs(b[i])) << i;
}

TEST(Catalog, RoundTrip) {
  const auto dir = nibrig::test::scratch_dir("catalog_round_trip");
  const Catalog original = sample_catalog();
  write_catalog(dir / "catalog.json", original);
  const Catalog back = read_catalog(dir / "catalog.json");

  EXPECT_EQ(back.citation, original.citation);
  EXPECT_EQ(back.notes, original.notes);
  ASSERT_EQ(back.tools.size(), 3u);
  EXPECT_EQ(back.tools[1].id, "vero1");
  EXPECT_EQ(back.tools[1].kind, "printed");
  EXPECT_EQ(back.tools[1].material, "vero");
  ASSERT_TRUE(back.tools[1].tip_diameter_m.has_value());
  EXPECT_NEAR(*back.tools[1].tip_diameter_m, 1e-3, 1e-15);
  EXPECT_FALSE(back.tools[0].tip_diameter_m.has_value());
  ASSERT_EQ(back.surfaces.size(), 2u);
  EXPECT_EQ(back.surfaces[0].name, "80 g office paper");
  ASSERT_EQ(back.pairings.size(), 3u);

  const Pairing& p = back.pairings[0];
  ASSERT_TRUE(p.friction && p.vibration);
  EXPECT_EQ(p.friction->mu, 0.21);
  EXPECT_EQ(p.friction->mu_ci_low, 0.19);
  EXPECT_EQ(p.friction->samples, 31885u);
  expect_near_all(p.friction->speeds_m_s, original.pairings[0].friction->speeds_m_s);
  EXPECT_EQ(p.friction->mu_by_speed, original.pairings[0].friction->mu_by_speed);
  EXPECT_EQ(p.friction->provenance.source, original.pairings[0].friction->provenance.source);
  EXPECT_EQ(p.vibration->spectrum.frequencies_hz, spectrum().frequencies_hz);
  expect_near_all(p.vibration->spectrum.speeds_m_s, spectrum().speeds_m_s);
  EXPECT_EQ(p.vibration->spectrum.amplitude_m_s2, spectrum().amplitude_m_s2);
  EXPECT_EQ(p.vibration->band_energies, original.pairings[0].vibration->band_energies);
  EXPECT_EQ(p.vibration->threshold_curve, "assets/threshold_curve.csv");
  EXPECT_EQ(p.vibration->weighted_power, 3.5);
  EXPECT_FALSE(back.pairings[1].friction.has_value());
  EXPECT_FALSE(back.pairings[2].vibration.has_value());

  // No temporary file is left beside the catalog.
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u);
}

TEST(Catalog, SpectrumJsonUsesExactlyTheAgreedKeysAndMillimetres) {
  const nlohmann::json json = to_json(spectrum());
  EXPECT_EQ(json.size(), 3u);
  EXPECT_EQ(json.at("frequencies_hz"), nlohmann::json({6.0, 50.0, 100.0, 250.0}));
  ASSERT_EQ(json.at("speeds_mm_s").size(), 3u);
  EXPECT_NEAR(json.at("speeds_mm_s")[0].get<double>(), 17.0, 1e-12);
  EXPECT_NEAR(json.at("speeds_mm_s")[2].get<double>(), 250.0, 1e-12);
  EXPECT_EQ(json.at("amplitude_m_s2")[2], nlohmann::json({0.1, 0.2, 0.3, 0.4}));
  const VelocitySpectrum back = velocity_spectrum_from_json(json, "x.json", "spectrum");
  expect_near_all(back.speeds_m_s, spectrum().speeds_m_s);
}

TEST(Catalog, SpectrumValidationNamesThePath) {
  nlohmann::json json = to_json(spectrum());
  json["amplitude_m_s2"][2].erase(1);
  expect_message_names(format_error_of([&] {
                         velocity_spectrum_from_json(json, "c.json", "pairings[3].vibration");
                       }),
                       {"c.json", "field 'pairings[3].vibration.amplitude_m_s2[2]'",
                        "expected 4 values (one per frequency), found 3"});
  json = to_json(spectrum());
  json["amplitude_m_s2"].erase(0);
  expect_message_names(format_error_of([&] { velocity_spectrum_from_json(json, "c.json", "v"); }),
                       {"field 'v.amplitude_m_s2'", "expected one row per speed (3), found 2"});
  json = to_json(spectrum());
  json["frequencies_hz"][2] = 40.0;
  expect_message_names(format_error_of([&] { velocity_spectrum_from_json(json, "c.json", "v"); }),
                       {"field 'v.frequencies_hz[2]'", "increasing order"});
  json = to_json(spectrum());
  json["amplitude_m_s2"][1][0] = -0.5;
  expect_message_names(format_error_of([&] { velocity_spectrum_from_json(json, "c.json", "v"); }),
                       {"field 'v.amplitude_m_s2[1][0]'", "expected 0 to 10000 (an acceleration amplitude"});
  json = to_json(spectrum());
  json["speeds_mm_s"][1] = "fast";
  expect_message_names(format_error_of([&] { velocity_spectrum_from_json(json, "c.json", "v"); }),
                       {"field 'v.speeds_mm_s[1]'", "expected a number, found the string 'fast'"});
  json = to_json(spectrum());
  json.erase("frequencies_hz");
  expect_message_names(format_error_of([&] { velocity_spectrum_from_json(json, "c.json", "v"); }),
                       {"field 'v.frequencies_hz'", "missing field"});
}

class CatalogMalformed : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = nibrig::test::scratch_dir("catalog_malformed");
    write_catalog(dir_ / "catalog.json", sample_catalog());
    std::ifstream in(dir_ / "catalog.json");
    json_ = nlohmann::json::parse(in);
  }
  std::string error_after(const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json json = json_;
    edit(json);
    nibrig::test::write_text(dir_ / "catalog.json", json.dump(2));
    return format_error_of([&] { read_catalog(dir_ / "catalog.json"); });
  }
  std::filesystem::path dir_;
  nlohmann::json json_;
};

TEST_F(CatalogMalformed, FieldErrorsNameTheJsonPath) {
  expect_message_names(
      error_after([](nlohmann::json& j) {
        j["pairings"][1]["vibration"]["amplitude_m_s2"][2].push_back(1.0);
      }),
      {"catalog.json", "field 'pairings[1].vibration.amplitude_m_s2[2]'", "expected 4 values"});
  expect_message_names(
      error_after([](nlohmann::json& j) { j["pairings"][0]["friction"].erase("mu"); }),
      {"field 'pairings[0].friction.mu'", "missing field"});
  expect_message_names(
      error_after([](nlohmann::json& j) { j["pairings"][0]["tool"] = "p8b"; }),
      {"field 'pairings[0].tool'", "expected a tool id listed in tools, found \"p8b\""});
  expect_message_names(error_after([](nlohmann::json& j) { j["tools"][2]["kind"] = "imaginary"; }),
                       {"field 'tools[2].kind'", "expected real, printed, commercial, predicted"});
  expect_message_names(error_after([](nlohmann::json& j) { j["tools"][1]["id"] = "p2h"; }),
                       {"field 'tools[1].id'", "listed twice"});
  expect_message_names(
      error_after(
          [](nlohmann::json& j) { j["pairings"][0]["vibration"]["band_energies"]["3"].erase(0); }),
      {"field 'pairings[0].vibration.band_energies.3'", "expected 3 band energies, found 2"});
  expect_message_names(error_after([](nlohmann::json& j) {
                         j["pairings"][0]["vibration"]["band_energies"]["x"] = {1.0};
                       }),
                       {"field 'pairings[0].vibration.band_energies.x'", "band count"});
  expect_message_names(
      error_after([](nlohmann::json& j) { j["pairings"][0]["friction"]["mu_by_speed"].erase(0); }),
      {"field 'pairings[0].friction.mu_by_speed'", "expected one value per speed (3), found 2"});
  expect_message_names(error_after([](nlohmann::json& j) {
                         j["pairings"][2]["surface"] = "office";
                         j["pairings"][2]["tool"] = "p2h";
                       }),
                       {"field 'pairings[2]'", "listed twice"});
  expect_message_names(error_after([](nlohmann::json& j) { j["format"] = "something-else"; }),
                       {"field 'format'", "expected \"nibrig-catalog\""});
  expect_message_names(error_after([](nlohmann::json& j) { j.erase("notes"); }),
                       {"field 'notes'", "missing field"});
}

// Physical quantities are bounded: μ = 1e300 would give inf in `space embed`, and an amplitude of
// 1e300 would make `forcing fit` write a file its own reader refuses.
TEST_F(CatalogMalformed, QuantitiesOutsideTheirPhysicalRangeAreNamed) {
  expect_message_names(error_after([](nlohmann::json& j) { j["pairings"][0]["friction"]["mu"] = 1e300; }),
                       {"field 'pairings[0].friction.mu'", "friction coefficient"});
  expect_message_names(
      error_after([](nlohmann::json& j) { j["pairings"][0]["friction"]["mu_by_speed"][1] = 12.0; }),
      {"field 'pairings[0].friction.mu_by_speed[1]'", "friction coefficient"});
  expect_message_names(
      error_after([](nlohmann::json& j) { j["pairings"][1]["vibration"]["amplitude_m_s2"][0][1] = 1e300; }),
      {"field 'pairings[1].vibration.amplitude_m_s2[0][1]'", "acceleration amplitude"});
  // Any number past 1e15 is refused whatever the field: nothing in these files is that large.
  expect_message_names(
      error_after([](nlohmann::json& j) { j["pairings"][0]["vibration"]["weighted_power"] = 1e300; }),
      {"field 'pairings[0].vibration.weighted_power'", "1e+15"});
}

TEST_F(CatalogMalformed, EmptyFileAndBadSyntax) {
  nibrig::test::write_text(dir_ / "catalog.json", "");
  expect_message_names(format_error_of([&] { read_catalog(dir_ / "catalog.json"); }),
                       {"catalog.json", "empty file"});
  nibrig::test::write_text(dir_ / "catalog.json", "{\n\"format\": \"nibrig-catalog\",\n\"tools\": [\n");
  expect_message_names(format_error_of([&] { read_catalog(dir_ / "catalog.json"); }),
                       {"catalog.json", "line 4", "invalid JSON"});
  // nlohmann reports a number beyond double range as out_of_range, not as a parse error.
  nibrig::test::write_text(dir_ / "catalog.json", "{\"format\": 1e999}");
  expect_message_names(format_error_of([&] { read_catalog(dir_ / "catalog.json"); }),
                       {"catalog.json", "invalid JSON", "number overflow"});
  expect_message_names(format_error_of([&] { read_catalog(dir_ / "missing.json"); }),
                       {"missing.json", "cannot open"});
}

TEST(Catalog, WriterRefusesNonFiniteNumbersAndLeavesTheOldFile) {
  const auto dir = nibrig::test::scratch_dir("catalog_writer_refuses");
  write_catalog(dir / "catalog.json", sample_catalog());
  Catalog bad = sample_catalog();
  bad.pairings[0].vibration->spectrum.amplitude_m_s2[1][2] =
      std::numeric_limits<double>::quiet_NaN();
  expect_message_names(
      format_error_of([&] { write_catalog(dir / "catalog.json", bad); }),
      {"catalog.json", "field 'pairings[0].vibration.amplitude_m_s2[1][2]'", "finite"});
  EXPECT_EQ(read_catalog(dir / "catalog.json").pairings.size(), 3u);  // the old catalog is intact
}

}  // namespace
}  // namespace nibrig::model::io
