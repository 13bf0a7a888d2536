#include "model/io/paper_friction.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

std::filesystem::path friction_dir() { return nibrig::test::shared_data() / "piovarci2018" / "friction"; }

std::vector<std::filesystem::path> friction_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(friction_dir())) {
    if (entry.is_regular_file() && entry.path().string().ends_with(".csv.gz"))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(FrictionFileName, ParsesTheDocumentedParts) {
  const auto name = parse_friction_file_name("x/vero1_glass_2.2N_13.7_1.csv.gz");
  EXPECT_EQ(name.tool, "vero1");
  EXPECT_EQ(name.surface, "glass");
  EXPECT_DOUBLE_EQ(name.normal_load_N, 2.2);
  EXPECT_DOUBLE_EQ(name.lever_factor, 13.7);
  EXPECT_EQ(name.repetition, 1);
  // A tool id with '_' still parses, because the parts are read from the right.
  EXPECT_EQ(parse_friction_file_name("DM851_nail1_note_2.2N_14_3.csv").tool, "DM851_nail1");
}

TEST(FrictionFileName, RejectsUnparsableNames) {
  for (const char* bad : {"vero1_glass_2.2N_13.7.csv.gz", "vero1_glass_2.2_13.7_1.csv.gz",
                          "vero1_glass_2.2N_x_1.csv.gz", "vero1_glass_2.2N_13.7_0.csv.gz",
                          "vero1_glass_2.2N_13.7_1.txt", "vero1__2.2N_13.7_1.csv"}) {
    expect_message_names(
        format_error_of([&] { parse_friction_file_name(bad); }),
        {bad, "unparsable file name", "expected <tool>_<surface>_<load>N_<lever>_<rep>.csv[.gz]"});
  }
}

// Every recording in the shared data parses; the lever factor comes from the name; the sensor runs
// at 1 kHz. The ±5 Hz band covers the measured 999.0-1001.0 Hz (USB batches of ~30 rows share a
// stamp, and the re-saved files count over whole seconds) while a misread time unit is far outside.
TEST(PaperFriction, EveryRealFileParsesAtOneKilohertz) {
  const auto files = friction_files();
  ASSERT_EQ(files.size(), 82u);  // 21 real, 7 commercial, 54 printed
  const std::regex pattern(R"(^(.+)_([a-z]+)_2\.2N_([0-9.]+)_([0-9]+)\.csv\.gz$)");
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const FrictionRecording recording = read_paper_friction(file);
    std::smatch match;
    const std::string leaf = file.filename().string();
    ASSERT_TRUE(std::regex_match(leaf, match, pattern));
    EXPECT_EQ(recording.name.tool, match[1].str());
    EXPECT_EQ(recording.name.surface, match[2].str());
    EXPECT_DOUBLE_EQ(recording.name.lever_factor, std::stod(match[3].str()));
    EXPECT_DOUBLE_EQ(recording.name.normal_load_N, 2.2);
    EXPECT_NEAR(recording.sample_rate_hz, 1000.0, 5.0);
    ASSERT_EQ(recording.time_s.size(), recording.tangential_force_N.size());
    EXPECT_GT(recording.time_s.size(), 30'000u);  // every recording is at least 30 s long
    EXPECT_TRUE(std::is_sorted(recording.time_s.begin(), recording.time_s.end()));
    EXPECT_EQ(recording.time_s.front(), 0.0);

    // Drag force at 2.2 N load: the 95th percentile of |F_t| must be a plausible friction force
    // (μ between 0.02 and 1). Forgetting the lever factor (×13-14) or the 403.2 counts/N would
    // land far outside; the real files span 0.18-0.81 N.
    std::vector<double> magnitude;
    for (double f : recording.tangential_force_N) magnitude.push_back(std::abs(f));
    std::nth_element(magnitude.begin(), magnitude.begin() + magnitude.size() * 95 / 100,
                     magnitude.end());
    const double p95 = magnitude[magnitude.size() * 95 / 100];
    EXPECT_GT(p95, 0.05);
    EXPECT_LT(p95, 2.2);
  }
}

TEST(PaperFriction, ConvertsCountsWithTheLeverFactorAndReadsUnpaddedMilliseconds) {
  // The first row of p2h_note is "10:8:52.800,0,-1,1" and the last "10:9:54.823,...,1015".
  const auto recording =
      read_paper_friction(friction_dir() / "real_tools" / "p2h_note_2.2N_14_1.csv.gz");
  EXPECT_EQ(recording.force_x_N.front(), 0.0);
  EXPECT_DOUBLE_EQ(recording.force_y_N.front(), -1.0 / 403.2 / 14.0);
  EXPECT_DOUBLE_EQ(recording.tangential_force_N.back(), 1015.0 / 403.2 / 14.0);
  EXPECT_NEAR(recording.time_s.back(), 62.023, 1e-9);
  EXPECT_NEAR(recording.sample_rate_hz, 62043.0 / 62.023, 1e-9);

  // apencil starts "18:55:23.76", "18:55:23.77", then "18:55:23.107": 76 ms, 77 ms, 107 ms. Read as
  // decimals (23.76 s then 23.107 s) time would run backwards.
  const auto apencil =
      read_paper_friction(friction_dir() / "comercial" / "apencil_glass_2.2N_14_1.csv.gz");
  const auto step = std::find_if(apencil.time_s.begin(), apencil.time_s.end(),
                                 [](double t) { return t > 0.0015; });
  ASSERT_NE(step, apencil.time_s.end());
  EXPECT_NEAR(*step, 0.031, 1e-9);
}

TEST(PaperFriction, ReportsTheQuirksOfTheRealFiles) {
  // stab_stone's last row "13:55:25.373,-1951,-750" lost its Z and line ending: dropped, with a
  // warning.
  const auto stab =
      read_paper_friction(friction_dir() / "real_tools" / "stab_stone_2.2N_14.1_1.csv.gz");
  EXPECT_EQ(stab.tangential_force_N.size(), 31885u);
  ASSERT_EQ(stab.warnings.size(), 1u);
  EXPECT_NE(stab.warnings[0].find("line 31887 is cut off"), std::string::npos) << stab.warnings[0];

  // vero1_glass was re-saved by a spreadsheet: "13:14.8" stamps, Z edited to non-integers.
  const auto vero =
      read_paper_friction(friction_dir() / "printed" / "vero1_glass_2.2N_13.7_1.csv.gz");
  EXPECT_EQ(vero.warnings.size(), 2u);
  EXPECT_NEAR(vero.sample_rate_hz, 1000.0, 5.0);
  // Uniform time: the whole recording spans rows / rate.
  EXPECT_NEAR(vero.time_s.back(), static_cast<double>(vero.time_s.size() - 1) / vero.sample_rate_hz,
              1e-9);
}

class FrictionMalformed : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = nibrig::test::scratch_dir("friction_malformed"); }
  std::filesystem::path write(const std::string& body,
                              const std::string& name = "p2h_note_2.2N_14_1.csv.gz") {
    nibrig::test::write_gzip(dir_ / name, body);
    return dir_ / name;
  }
  std::filesystem::path dir_;
};

std::string friction_rows(int count, int start_ms = 0) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    const int ms = start_ms + i;
    text += "10:8:" + std::to_string(52 + ms / 1000) + "." + std::to_string(ms % 1000) + ",1,2,3\n";
  }
  return text;
}

TEST_F(FrictionMalformed, TruncatedGzip) {
  std::string body = "TimeStamp,X,Y,Z\n";
  for (int i = 0; i < 20000; ++i) {
    body += "10:" + std::to_string(10 + i / 60000) + ":" + std::to_string((i / 1000) % 60) + "." +
            std::to_string(i % 1000) + "," + std::to_string((i * 7919) % 2003) + "," +
            std::to_string((i * 104729) % 1999) + "," + std::to_string((i * 13) % 997) + "\n";
  }
  nibrig::test::write_truncated_gzip(dir_ / "p2h_note_2.2N_14_1.csv.gz", body, 0.6);
  expect_message_names(
      format_error_of([&] { read_paper_friction(dir_ / "p2h_note_2.2N_14_1.csv.gz"); }),
      {"p2h_note_2.2N_14_1.csv.gz", "line ", "compressed data is truncated"});
}

TEST_F(FrictionMalformed, NonNumericField) {
  const auto file = write("TimeStamp,X,Y,Z\n10:8:52.800,0,-1,1\n10:8:52.801,0,abc,1\n");
  expect_message_names(
      format_error_of([&] { read_paper_friction(file); }),
      {"p2h_note_2.2N_14_1.csv.gz", "line 3, field 'Y'", "expected a number, found 'abc'"});
}

TEST_F(FrictionMalformed, NaNField) {
  const auto file = write("TimeStamp,X,Y,Z\n10:8:52.800,0,-1,nan\n10:8:52.801,0,1,1\n");
  expect_message_names(
      format_error_of([&] { read_paper_friction(file); }),
      {"p2h_note_2.2N_14_1.csv.gz", "line 2, field 'Z'", "expected a finite number"});
}

// Issue 46: a count of 1e308 is named by line and field, as the force it would be at the tip.
TEST_F(FrictionMalformed, ACountBeyondAnyTipForceIsNamedByLine) {
  const auto file = write("TimeStamp,X,Y,Z\n10:8:52.800,0,-1,1\n10:8:52.801,0,1e308,1\n");
  expect_message_names(format_error_of([&] { read_paper_friction(file); }),
                       {"p2h_note_2.2N_14_1.csv.gz", "line 3, field 'Y'",
                        "expected a force at the tip of at most 1000 N, found 1e+308 counts"});
}

// A load stated for a file named otherwise (a face's --load, Python's load=) is held to the same
// range as a name's: 1e-320 N ended in "autocorrelation: non-finite sample".
TEST_F(FrictionMalformed, AStatedLoadOrLeverOutsideItsRangeIsNamed) {
  const auto file = write("TimeStamp,X,Y,Z\n" + friction_rows(10), "anything.csv.gz");
  FrictionFileName name;
  name.tool = "p2h", name.surface = "note", name.normal_load_N = 1e-320, name.lever_factor = 14.0;
  EXPECT_THAT([&] { read_paper_friction(file, name); },
              ::testing::ThrowsMessage<std::invalid_argument>(::testing::AllOf(
                  ::testing::HasSubstr("anything.csv.gz"),
                  ::testing::HasSubstr("load 9.99989e-321 N: expected a normal load in N, 0.01 to 50"))));
  name.normal_load_N = 2.2, name.lever_factor = 1e308;
  EXPECT_THAT([&] { read_paper_friction(file, name); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  ::testing::HasSubstr("lever 1e+308: expected a lever factor, 0.1 to 100")));
}

TEST_F(FrictionMalformed, MissingColumn) {
  const auto file = write("TimeStamp,X,Y\n10:8:52.800,0,-1\n");
  expect_message_names(
      format_error_of([&] { read_paper_friction(file); }),
      {"p2h_note_2.2N_14_1.csv.gz", "line 1", "missing column 'Z'", "TimeStamp,X,Y,Z"});
}

TEST_F(FrictionMalformed, EmptyFileAndHeaderOnly) {
  const auto empty = write("");
  expect_message_names(format_error_of([&] { read_paper_friction(empty); }),
                       {"p2h_note_2.2N_14_1.csv.gz", "empty file", "TimeStamp,X,Y,Z"});
  const auto header_only = write("TimeStamp,X,Y,Z\n", "p2h_office_2.2N_14_1.csv.gz");
  expect_message_names(format_error_of([&] { read_paper_friction(header_only); }),
                       {"p2h_office_2.2N_14_1.csv.gz", "expected at least 2 data rows", "found 0"});
}

TEST_F(FrictionMalformed, UnparsableFileName) {
  const auto file = write("TimeStamp,X,Y,Z\n" + friction_rows(3), "friction.csv.gz");
  expect_message_names(
      format_error_of([&] { read_paper_friction(file); }),
      {"friction.csv.gz", "unparsable file name", "<tool>_<surface>_<load>N_<lever>_<rep>"});
}

TEST_F(FrictionMalformed, BadOrBackwardTimestamps) {
  const auto bad = write("TimeStamp,X,Y,Z\n10:8:52.800,0,-1,1\n10:61:52.801,0,1,1\n");
  expect_message_names(
      format_error_of([&] { read_paper_friction(bad); }),
      {"line 3, field 'TimeStamp'", "expected a wall-clock time H:M:S.ms", "10:61:52.801"});
  const auto backwards = write("TimeStamp,X,Y,Z\n10:8:52.800,0,-1,1\n10:8:51.900,0,1,1\n",
                               "p2h_stone_2.2N_14_1.csv.gz");
  expect_message_names(
      format_error_of([&] { read_paper_friction(backwards); }),
      {"p2h_stone_2.2N_14_1.csv.gz", "line 3, field 'TimeStamp'", "expected time to increase"});
  const auto mixed =
      write("TimeStamp,X,Y,Z\n10:8:52.800,0,-1,1\n8:52.9,0,1,1\n", "p8b_note_2.2N_14_1.csv.gz");
  expect_message_names(format_error_of([&] { read_paper_friction(mixed); }),
                       {"line 3, field 'TimeStamp'", "same time format as the first row"});
}

TEST_F(FrictionMalformed, WrongSampleRate) {
  std::string body = "TimeStamp,X,Y,Z\n";
  for (int i = 0; i < 50; ++i)
    body +=
        "10:8:" + std::to_string(10 + i / 100) + "." + std::to_string(i * 10 % 1000) + ",1,2,3\n";
  const auto file = write(body);  // one row every 10 ms: 100 Hz
  expect_message_names(
      format_error_of([&] { read_paper_friction(file); }),
      {"p2h_note_2.2N_14_1.csv.gz", "column 'TimeStamp'", "expected about 1000 Hz", "found 100.0"});
}

TEST_F(FrictionMalformed, ShortRowInsideTheDataIsAnError) {
  const auto file =
      write("TimeStamp,X,Y,Z\n10:8:52.800,0,-1,1\n10:8:52.801,0\n10:8:52.802,0,1,1\n");
  expect_message_names(format_error_of([&] { read_paper_friction(file); }),
                       {"line 3", "expected 4 fields (TimeStamp,X,Y,Z), found 2"});
}

TEST_F(FrictionMalformed, WrapPastMidnightKeepsTimeIncreasing) {
  const auto file = write(
      "TimeStamp,X,Y,Z\n23:59:59.998,0,0,1\n23:59:59.999,0,0,1\n0:0:0.0,0,0,1\n0:0:0.1,0,0,1\n");
  const auto recording = read_paper_friction(file);
  ASSERT_EQ(recording.time_s.size(), 4u);
  EXPECT_NEAR(recording.time_s[2], 0.002, 1e-9);
  EXPECT_NEAR(recording.time_s[3], 0.003, 1e-9);  // "0.1" is 1 ms: milliseconds are unpadded
  // Times near 86400 s carry ~1e-11 s of rounding; over a 3 ms span that is ~1e-5 Hz.
  EXPECT_NEAR(recording.sample_rate_hz, 1000.0, 1e-3);
}

// Issue 46: a lever of 1e308 in a file's name gave μ 1.7e-308; the name is held to the range the
// --lever option has, and names the file and what was expected.
TEST(PaperFrictionBounds, ANameOutsideTheOptionsRangesIsRefused) {
  try {
    parse_friction_file_name("vero1_glass_2.2N_1e308_1.csv");
    FAIL() << "a lever factor of 1e308 passed";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("vero1_glass_2.2N_1e308_1.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("lever factor"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.1 to 100"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_friction_file_name("vero1_glass_1e-300N_13.7_1.csv"), FormatError);
  EXPECT_NO_THROW(parse_friction_file_name("vero1_glass_2.2N_13.7_1.csv"));
}

}  // namespace
}  // namespace nibrig::model::io
