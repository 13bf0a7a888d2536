#include "model/io/paper_vibration.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "model/io/paper_friction.hpp"
#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

std::filesystem::path vibration_data() { return nibrig::test::shared_data() / "piovarci2018"; }

std::vector<std::filesystem::path> files_under(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().string().ends_with(".csv.gz"))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(VibrationFileName, EveryDocumentedForm) {
  struct Case {
    const char* file;
    const char* tool;
    const char* material;
    std::optional<double> tip_m;
    const char* variant;
    const char* surface;
  };
  const Case cases[] = {
      {"arm_p2h_office.csv.gz", "p2h", "", std::nullopt, "", "office"},
      {"arm_apencil_glass.csv.gz", "apencil", "", std::nullopt, "", "glass"},
      {"arm_vero_1_glass.csv.gz", "vero1", "vero", 1e-3, "", "glass"},
      {"arm_DM85_2_protector.csv.gz", "DM852", "DM85", 2e-3, "", "protector"},
      {"arm_teflon_4_stone.csv.gz", "teflon4", "teflon", 4e-3, "", "stone"},
      {"arm_plain_DM95_1_note.csv", "DM951", "DM95", 1e-3, "plain", "note"},
      {"arm_plain_DM85_1_nail1_note.csv.gz", "DM851_nail1", "DM85", 1e-3, "nail1", "note"},
      {"arm_penh_DM85_office.csv.gz", "penh_DM85", "DM85", std::nullopt, "penh", "office"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const auto name = parse_vibration_file_name(c.file);
    EXPECT_EQ(name.tool, c.tool);
    EXPECT_EQ(name.material, c.material);
    ASSERT_EQ(name.tip_diameter_m.has_value(), c.tip_m.has_value());
    if (c.tip_m) {
      EXPECT_DOUBLE_EQ(*name.tip_diameter_m, *c.tip_m);
    }
    EXPECT_EQ(name.variant, c.variant);
    EXPECT_EQ(name.surface, c.surface);
  }
}

TEST(VibrationFileName, RejectsUnparsableNames) {
  for (const char* bad : {"vero_1_glass.csv.gz", "arm_glass.csv.gz", "arm_plain_vero_glass.csv.gz",
                          "arm_vero_x_1_glass.csv.gz", "arm_penh_DM85_1_note.csv.gz",
                          "arm_vero_0_glass.csv.gz", "arm_p2h_office.wav", "arm_p2h__office.csv"}) {
    expect_message_names(format_error_of([&] { parse_vibration_file_name(bad); }),
                         {bad, "unparsable file name", "expected arm_<tool>_<surface>"});
  }
}

TEST(VibrationFileName, TimestampListIsNotARecording) {
  EXPECT_FALSE(is_paper_vibration_file(vibration_data() / "vibration" / "prints" / "ts.csv.gz"));
  EXPECT_TRUE(is_paper_vibration_file("arm_vero_1_glass.csv.gz"));
  EXPECT_FALSE(is_paper_vibration_file("arm_.csv.gz"));
}

// Every recording parses; the ±2 % rate check inside the reader passed for each; gaps are where the
// timestamps say. 86 recordings + ts.csv.gz.
TEST(PaperVibration, EveryRealRecordingParses) {
  const auto files = files_under(vibration_data() / "vibration");
  std::size_t recordings = 0;
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    if (!is_paper_vibration_file(file)) {
      EXPECT_EQ(file.filename(), "ts.csv.gz");
      continue;
    }
    ++recordings;
    const VibrationRecording recording = read_paper_vibration(file);
    EXPECT_EQ(recording.sample_rate_hz, 1000.0);
    ASSERT_EQ(recording.time_s.size(), recording.acceleration_m_s2.size());
    EXPECT_GT(recording.acceleration_m_s2.size(), 40'000u);  // every recording is 42-53 s
    for (std::size_t gap : recording.timestamp_gaps) {
      ASSERT_GT(gap, 0u);
      EXPECT_GT(std::abs(recording.time_s[gap] - recording.time_s[gap - 1] - 1e-3), 1e-6);
    }
    // The enclosure rests on the arm with gravity mostly along x: the mean is near +1 g (the real
    // files span 0.75-0.97 g in their first row). A missing g→m/s² conversion would give ~0.9.
    double mean = 0.0;
    for (double a : recording.acceleration_m_s2) mean += a;
    mean /= static_cast<double>(recording.acceleration_m_s2.size());
    EXPECT_GT(mean, 0.5 * kStandardGravity_m_s2);
    EXPECT_LT(mean, 1.5 * kStandardGravity_m_s2);
  }
  EXPECT_EQ(recordings, 86u);
}

TEST(PaperVibration, BlankHeaderFileAndItsPauseBetweenSweeps) {
  // arm_plain_vero_4_stone has the blank header ",,,,,"; its first row is
  // ",1513252351136,0.91219515,...", and between rows 14000 and 14001 (0-based) the stamps jump by
  // 26069 ms (checked with awk on the file itself).
  const auto recording =
      read_paper_vibration(vibration_data() / "vibration" / "prints" / "arm_plain_vero_4_stone.csv.gz");
  EXPECT_EQ(recording.name.tool, "vero4");
  EXPECT_EQ(recording.name.variant, "plain");
  EXPECT_EQ(recording.acceleration_m_s2.size(), 42003u);
  EXPECT_DOUBLE_EQ(recording.acceleration_m_s2.front(), 0.91219515 * 9.80665);
  EXPECT_NEAR(recording.time_s[14001] - recording.time_s[14000], 26.069, 1e-9);
  EXPECT_NE(std::find(recording.timestamp_gaps.begin(), recording.timestamp_gaps.end(), 14001u),
            recording.timestamp_gaps.end());
}

// Where the same physical tool was measured for friction, the ids agree, so the catalog can pair
// them. Pen-holder and nail variants were only recorded for vibration.
TEST(PaperVibration, ToolIdsMatchTheFrictionFiles) {
  std::set<std::string> friction_tools;
  for (const auto& file : files_under(vibration_data() / "friction")) {
    friction_tools.insert(parse_friction_file_name(file).tool);
  }
  for (const auto& file : files_under(vibration_data() / "vibration")) {
    if (!is_paper_vibration_file(file)) continue;
    const auto name = parse_vibration_file_name(file);
    if (name.variant == "penh" || name.variant.starts_with("nail")) continue;
    EXPECT_TRUE(friction_tools.count(name.tool)) << file << " -> " << name.tool;
  }
}

class VibrationMalformed : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = nibrig::test::scratch_dir("vibration_malformed"); }
  std::filesystem::path write(const std::string& body,
                              const std::string& name = "arm_vero_1_glass.csv.gz") {
    nibrig::test::write_gzip(dir_ / name, body);
    return dir_ / name;
  }
  std::filesystem::path dir_;
};

std::string header() { return "time,timestamp,xAccel,yAccel,zAccel,xxx\n"; }

std::string vibration_rows(int count, int step_ms = 1, long long start = 1515589189348) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    text += "2018-1-10T13-59-49," + std::to_string(start + i * step_ms) + ",0.87,-0.06,0.50,0.87\n";
  }
  return text;
}

TEST_F(VibrationMalformed, ReadsAWellFormedFileAndRecordsGaps) {
  // 400 samples, then 8 ms without one (7 dropped samples), then 400 more: 1000 Hz within 1 %.
  std::string body = header() + vibration_rows(400, 1, 1'000'000);
  body += "t,1000407,1.0,0,0,1.0\n";
  body += vibration_rows(399, 1, 1'000'408);
  const auto recording = read_paper_vibration(write(body));
  ASSERT_EQ(recording.acceleration_m_s2.size(), 800u);
  EXPECT_EQ(recording.timestamp_gaps, (std::vector<std::size_t>{400}));
  EXPECT_NEAR(recording.time_s[400], 0.407, 1e-12);
  EXPECT_DOUBLE_EQ(recording.acceleration_m_s2[400], 9.80665);
  EXPECT_DOUBLE_EQ(recording.acceleration_m_s2[0], 0.87 * 9.80665);
}

TEST_F(VibrationMalformed, TruncatedGzip) {
  std::string body = header();
  for (int i = 0; i < 20000; ++i) {
    body += "t," + std::to_string(1515589189348LL + i) + "," +
            std::to_string((i * 7919) % 2003 / 1000.0) + "," +
            std::to_string((i * 104729) % 1999 / 1000.0) + ",0.5,0.1\n";
  }
  nibrig::test::write_truncated_gzip(dir_ / "arm_vero_1_glass.csv.gz", body, 0.5);
  expect_message_names(
      format_error_of([&] { read_paper_vibration(dir_ / "arm_vero_1_glass.csv.gz"); }),
      {"arm_vero_1_glass.csv.gz", "line ", "compressed data is truncated"});
}

TEST_F(VibrationMalformed, NonNumericField) {
  const auto file = write(header() + vibration_rows(3) + "t,1515589189351,zero,0,0,0\n");
  expect_message_names(
      format_error_of([&] { read_paper_vibration(file); }),
      {"arm_vero_1_glass.csv.gz", "line 5, field 'xAccel'", "expected a number, found 'zero'"});
}

TEST_F(VibrationMalformed, NaNField) {
  const auto file = write(header() + vibration_rows(3) + "t,1515589189351,NaN,0,0,0\n");
  expect_message_names(
      format_error_of([&] { read_paper_vibration(file); }),
      {"arm_vero_1_glass.csv.gz", "line 5, field 'xAccel'", "expected a finite number"});
}

// Issue 46: 1e308 g inside a recording reached step segmentation ("no sweep of 6 moving blocks
// found"); it is named by line and field with the largest acceleration a stylus is read to have.
TEST_F(VibrationMalformed, AnAccelerationBeyondAnyStylusIsNamedByLine) {
  for (const char* value : {"1e308", "-1000.5"}) {
    const auto file = write(header() + vibration_rows(3) + "t,1515589189351," + value + ",0,0,0\n");
    expect_message_names(format_error_of([&] { read_paper_vibration(file); }),
                         {"arm_vero_1_glass.csv.gz", "line 5, field 'xAccel'",
                          "expected an acceleration in g of at most 1000", std::string("found '") + value + "'"});
  }
  // 1000 g itself is a value, if an implausible one.
  EXPECT_NO_THROW(read_paper_vibration(write(header() + vibration_rows(3) + "t,1515589189351,1000,0,0,0\n")));
}

TEST_F(VibrationMalformed, MissingColumn) {
  const auto file = write("time,stamp,xAccel\n" + vibration_rows(3));
  expect_message_names(
      format_error_of([&] { read_paper_vibration(file); }),
      {"arm_vero_1_glass.csv.gz", "line 1", "missing column 'timestamp'", "time,timestamp,xAccel"});
}

TEST_F(VibrationMalformed, EmptyFile) {
  const auto file = write("");
  expect_message_names(format_error_of([&] { read_paper_vibration(file); }),
                       {"arm_vero_1_glass.csv.gz", "empty file", "time,timestamp,xAccel"});
}

TEST_F(VibrationMalformed, UnparsableFileName) {
  const auto file = write(header() + vibration_rows(3), "vibration.csv.gz");
  expect_message_names(format_error_of([&] { read_paper_vibration(file); }),
                       {"vibration.csv.gz", "unparsable file name", "arm_<tool>_<surface>"});
}

TEST_F(VibrationMalformed, WrongSampleRate) {
  const auto slow = write(header() + vibration_rows(100, 2));  // 500 Hz
  expect_message_names(
      format_error_of([&] { read_paper_vibration(slow); }),
      {"arm_vero_1_glass.csv.gz", "column 'timestamp'", "expected 1000 Hz, found 500"});
  std::string fast_body = header();  // two rows per millisecond: 99 steps over 49 ms
  for (int i = 0; i < 100; ++i) fast_body += "t," + std::to_string(1000 + i / 2) + ",1,0,0,1\n";
  const auto fast = write(fast_body, "arm_vero_2_glass.csv.gz");
  expect_message_names(format_error_of([&] { read_paper_vibration(fast); }),
                       {"arm_vero_2_glass.csv.gz", "expected 1000 Hz, found 2020.4"});
}

TEST_F(VibrationMalformed, BackwardOrFractionalTimestamps) {
  const auto backwards = write(header() + vibration_rows(3) + "t,1515589189000,1,0,0,1\n");
  expect_message_names(format_error_of([&] { read_paper_vibration(backwards); }),
                       {"line 5, field 'timestamp'", "expected time to increase"});
  const auto fractional =
      write(header() + "t,1515589189348.5,1,0,0,1\n", "arm_vero_4_glass.csv.gz");
  expect_message_names(
      format_error_of([&] { read_paper_vibration(fractional); }),
      {"arm_vero_4_glass.csv.gz", "line 2, field 'timestamp'", "expected a whole number"});
}

}  // namespace
}  // namespace nibrig::model::io
