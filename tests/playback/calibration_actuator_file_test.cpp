#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "model/io/format_error.hpp"
#include "playback/actuator_file.hpp"
#include "tests/playback/calibration_chain.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::playback {
namespace {

// A calibration as the live command would make it: the chain's response on a log grid (the sweep's
// estimate has that form), the default design at 4 kHz.
ActuatorCalibration example() {
  const testing::ChainModel chain;
  ActuatorCalibration c;
  c.name = "haptuator-mk2 #3";
  c.created = "2025-01-31T14:05:00Z";
  c.delay_s = 173.0 / 48000.0;
  for (double f = 11.0; f <= 18000.0; f *= std::exp2(1.0 / 24.0)) {
    c.response.frequencies_hz.push_back(f);
    c.response.values.push_back(testing::analogue_response(chain, f));
  }
  c.filter = design_inverse_filter(c.response, c.design);
  return c;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

// The message of the FormatError reading `file` throws; "" when it throws none.
std::string read_error(const std::filesystem::path& file) {
  try {
    read_actuator_file(file);
  } catch (const model::io::FormatError& error) {
    return error.what();
  }
  return "";
}

TEST(CalibrationActuatorFile, RoundTripsEveryField) {
  const auto file = nibrig::test::scratch_dir("actuator_round_trip") / "actuator.json";
  const ActuatorCalibration c = example();
  write_actuator_file(file, c);
  const ActuatorCalibration back = read_actuator_file(file);
  EXPECT_EQ(back.name, c.name);
  EXPECT_EQ(back.created, c.created);
  EXPECT_EQ(back.sweep.end_hz, c.sweep.end_hz);
  EXPECT_EQ(back.sweep.repetitions, c.sweep.repetitions);
  EXPECT_EQ(back.delay_s, c.delay_s);  // JSON numbers are written to round-trip exactly
  ASSERT_EQ(back.response.values.size(), c.response.values.size());
  for (std::size_t i = 0; i < c.response.values.size(); ++i) {
    EXPECT_EQ(back.response.frequencies_hz[i], c.response.frequencies_hz[i]);
    // Stored as magnitude and phase: polar() and back costs a few ulps.
    EXPECT_NEAR(std::abs(back.response.values[i] - c.response.values[i]), 0.0,
                1e-14 * std::abs(c.response.values[i]));
  }
  EXPECT_EQ(back.filter.taps, c.filter.taps);
  EXPECT_EQ(back.filter.sample_rate_hz, 4000.0);
  EXPECT_EQ(back.design.taps, c.design.taps);
  EXPECT_EQ(back.design.band_low_hz, 20.0);
  EXPECT_EQ(back.design.max_boost_db, c.design.max_boost_db);
  EXPECT_EQ(back.filter.max_deviation_db, c.filter.max_deviation_db);
  EXPECT_EQ(back.filter.group_delay_100hz_s, c.filter.group_delay_100hz_s);
  // The format the brief fixes, by name.
  const nlohmann::json j = nlohmann::json::parse(read_text(file));
  EXPECT_EQ(j["format"], "nibrig-actuator");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["band_hz"], nlohmann::json::array({20.0, 500.0}));
  EXPECT_TRUE(j["flatness_db"].contains("max_deviation"));
}

TEST(CalibrationActuatorFile, RedesignsForAnotherRateFromTheStoredResponse) {
  const auto file = nibrig::test::scratch_dir("actuator_redesign") / "actuator.json";
  write_actuator_file(file, example());
  const ActuatorCalibration c = read_actuator_file(file);
  const double rate = 44100.0 / 11.0;  // a 44.1 kHz device
  const InverseFilter filter = redesign_for_rate(c, rate);
  EXPECT_EQ(filter.sample_rate_hz, rate);
  EXPECT_EQ(filter.taps.size(), 257u);  // 64 ms, as the stored 256 taps at 4 kHz
  // Judged against the closed form, not the stored response: ±1 dB over the band, as at 4 kHz.
  const testing::ChainModel chain;
  double worst = 0;
  for (double f = 20.0; f <= 500.0; f += 1.0) {
    const std::complex<double> g = fir_response(filter.taps, f, rate);
    worst = std::max(
        worst, std::abs(20.0 * std::log10(std::abs(testing::analogue_response(chain, f) * g))));
  }
  EXPECT_LT(worst, 1.0);
}

TEST(CalibrationActuatorFile, ABadFieldNamesTheFileThePathAndWhatWasExpected) {
  const auto dir = nibrig::test::scratch_dir("actuator_bad_field");
  const auto good = dir / "good.json";
  write_actuator_file(good, example());
  const nlohmann::json original = nlohmann::json::parse(read_text(good));

  struct Case {
    const char* name;
    void (*edit)(nlohmann::json&);
    const char* path;
    const char* expected;
  };
  const Case cases[] = {
      {"magnitude", [](nlohmann::json& j) { j["response"]["magnitude"][3] = "loud"; },
       "field 'response.magnitude[3]'", "expected a number"},
      {"negative", [](nlohmann::json& j) { j["response"]["magnitude"][5] = -1.0; },
       "field 'response.magnitude[5]'", "expected a positive magnitude"},
      {"short phase", [](nlohmann::json& j) { j["response"]["phase_rad"].erase(0); },
       "field 'response.phase_rad'", "values (one per frequency)"},
      {"missing taps", [](nlohmann::json& j) { j["filter"].erase("taps"); }, "field 'filter.taps'",
       "missing field"},
      {"rate", [](nlohmann::json& j) { j["filter"]["sample_rate_hz"] = 48000; },
       "field 'filter.sample_rate_hz'", "2000 to 8000 Hz"},
      {"format", [](nlohmann::json& j) { j["format"] = "nibrig-session"; }, "field 'format'",
       "expected \"nibrig-actuator\""},
      {"repetitions", [](nlohmann::json& j) { j["sweep"]["repetitions"] = 0; },
       "field 'sweep.repetitions'", "whole number in [1, 100]"},
      {"sweep", [](nlohmann::json& j) { j["sweep"]["end_hz"] = 30000.0; }, "field 'sweep'",
       "below Nyquist"},
      {"band",
       [](nlohmann::json& j) {
         j["band_hz"] = {500, 20};
       },
       "field 'band_hz'", "0 < low < high"},
  };
  for (const Case& c : cases) {
    nlohmann::json edited = original;
    c.edit(edited);
    const auto file = dir / (std::string(c.name) + ".json");
    write_text(file, edited.dump());
    const std::string message = read_error(file);
    EXPECT_NE(message.find(file.string()), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find(c.path), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.name << ": " << message;
  }
}

TEST(CalibrationActuatorFile, ATruncatedOrEmptyFileIsAClearError) {
  const auto dir = nibrig::test::scratch_dir("actuator_truncated");
  const auto good = dir / "good.json";
  write_actuator_file(good, example());
  const std::string text = read_text(good);
  const auto truncated = dir / "truncated.json";
  write_text(truncated, text.substr(0, text.size() / 2));  // as a crash mid-write would leave it
  const std::string message = read_error(truncated);
  EXPECT_NE(message.find(truncated.string()), std::string::npos) << message;
  EXPECT_NE(message.find("invalid JSON"), std::string::npos) << message;

  const auto empty = dir / "empty.json";
  write_text(empty, "");
  EXPECT_NE(read_error(empty).find("empty file"), std::string::npos);
  EXPECT_NE(read_error(dir / "missing.json").find("cannot open"), std::string::npos);
}

}  // namespace
}  // namespace nibrig::playback
