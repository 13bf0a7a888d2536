#include "model/io/paper_drawing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

std::vector<std::filesystem::path> drawing_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(nibrig::test::shared_data() / "piovarci2018" / "drawing")) {
    if (entry.path().string().ends_with(".csv.gz")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

TEST(PaperDrawing, NameSplitsToolSurfaceAndSubject) {
  const auto dir = nibrig::test::scratch_dir("drawing_name");
  nibrig::test::write_gzip(dir / "p2h_paper_bottle_c2.csv.gz",
                   "Unix Timestamp,X,Y,Z,Phi,Theta,F,Ground,Touch,Speed,Acceeration\n"
                   "1000,1,2,3,0,0,0.5,0,1,0,0\n1008,1.3,2.4,3,0,0,0.6,0,1,0.5,0\n");
  const auto trajectory = read_paper_drawing(dir / "p2h_paper_bottle_c2.csv.gz");
  EXPECT_EQ(trajectory.tool, "p2h");
  EXPECT_EQ(trajectory.surface, "paper");
  EXPECT_EQ(trajectory.subject, "bottle_c2");
  EXPECT_DOUBLE_EQ(trajectory.frame_rate_hz, 125.0);
  EXPECT_DOUBLE_EQ(trajectory.x_m[1], 1.3e-3);
  EXPECT_DOUBLE_EQ(trajectory.speed_m_s[1], 0.5 * 125.0 * 1e-3);
  EXPECT_EQ(trajectory.touching, (std::vector<bool>{true, true}));
}

// All 86 trajectories parse, the frame rate is the tablet's (~120 Hz: 111-139 Hz across the files,
// the band allows for that spread), and the speeds are those of hands drawing.
TEST(PaperDrawing, EveryRealFileParsesWithPlausibleRatesAndSpeeds) {
  const auto files = drawing_files();
  ASSERT_EQ(files.size(), 86u);
  std::size_t without_touch = 0;
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const DrawingTrajectory t = read_paper_drawing(file);
    EXPECT_GT(t.frame_rate_hz, 100.0);
    EXPECT_LT(t.frame_rate_hz, 150.0);
    EXPECT_TRUE(std::is_sorted(t.time_s.begin(), t.time_s.end()));
    std::vector<double> touching_speeds;
    for (std::size_t i = 0; i < t.speed_m_s.size(); ++i) {
      if (t.touching[i]) touching_speeds.push_back(t.speed_m_s[i]);
    }
    if (touching_speeds.empty()) {
      ++without_touch;
      continue;
    }
    // The 95th percentile of the drawing speed is 91-457 mm/s across the files; strokes faster than
    // 1 m/s or a whole file slower than 50 mm/s would mean a unit or rate error.
    std::nth_element(touching_speeds.begin(),
                     touching_speeds.begin() + touching_speeds.size() * 95 / 100,
                     touching_speeds.end());
    const double p95 = touching_speeds[touching_speeds.size() * 95 / 100];
    EXPECT_GT(p95, 0.05);
    EXPECT_LT(p95, 1.0);
  }
  // p2h_paper_cone, _cube and _cylinder never set the Touch flag (force and motion are there).
  EXPECT_EQ(without_touch, 3u);
}

// The Speed column against the positions and timestamps, two ways.
TEST(PaperDrawing, SpeedColumnAgreesWithFiniteDifferencesOfPosition) {
  for (const auto& file : drawing_files()) {
    SCOPED_TRACE(file.string());
    const DrawingTrajectory t = read_paper_drawing(file);
    // 1. Per frame, Speed is the in-plane distance to the previous frame. The positions are written
    //    with 0.01 mm resolution, so a distance recomputed from them can differ by up to
    //    √2 × 0.01 mm ≈ 0.014 mm; 0.015 mm allows for that and nothing more. After a tracking
    //    dropout (step > 50 ms) the recorder's previous frame is not in the file, so those frames
    //    are left out (p2h_paper_ball has 3 of them, the other files none).
    double worst_mm = 0.0;
    for (std::size_t i = 1; i < t.x_m.size(); ++i) {
      if (t.time_s[i] - t.time_s[i - 1] > 0.050) continue;
      const double step_mm = std::hypot(t.x_m[i] - t.x_m[i - 1], t.y_m[i] - t.y_m[i - 1]) * 1e3;
      const double column_mm = t.speed_m_s[i] / t.frame_rate_hz * 1e3;
      worst_mm = std::max(worst_mm, std::abs(step_mm - column_mm));
    }
    EXPECT_LT(worst_mm, 0.015);

    // 2. Over 1 s stretches of tracking (no step above 50 ms) with the pen moving faster than
    //    5 mm/s, the mean of speed_m_s against path length / elapsed time from the timestamps. The
    //    local frame rate wanders (6-16 ms steps), so single windows scatter by ±15 %; the median
    //    over a file's windows must be within 8 % (real files: 0.94-1.01). A rate taken as the
    //    median of 1/Δt (125 or 142.9 Hz) would put most files at 1.10-1.25.
    std::vector<double> ratios;
    std::size_t i = 1;
    while (i < t.time_s.size()) {
      double elapsed = 0.0, path = 0.0, column_sum = 0.0;
      std::size_t n = 0, j = i;
      while (j < t.time_s.size() && elapsed < 1.0) {
        const double dt = t.time_s[j] - t.time_s[j - 1];
        if (dt > 0.050) break;
        elapsed += dt;
        path += std::hypot(t.x_m[j] - t.x_m[j - 1], t.y_m[j] - t.y_m[j - 1]);
        column_sum += t.speed_m_s[j];
        ++n;
        ++j;
      }
      if (elapsed >= 1.0 && path / elapsed > 0.005)
        ratios.push_back(column_sum / static_cast<double>(n) / (path / elapsed));
      i = j == i ? j + 1 : j;
    }
    ASSERT_GT(ratios.size(), 20u);
    EXPECT_NEAR(median(ratios), 1.0, 0.08);
  }
}

class DrawingMalformed : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = nibrig::test::scratch_dir("drawing_malformed"); }
  std::filesystem::path write(const std::string& body,
                              const std::string& name = "pen_paper_cube.csv.gz") {
    nibrig::test::write_gzip(dir_ / name, body);
    return dir_ / name;
  }
  std::filesystem::path dir_;
};

const std::string kHeader = "Unix Timestamp,X,Y,Z,Phi,Theta,F,Ground,Touch,Speed,Acceeration\n";

std::string drawing_rows(int count) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    text += std::to_string(1492954983454LL + 8 * i) +
            ",89.62,209.88,24.81,49.89,-62.55,-0.6,295.63,0,0.22,0.1\n";
  }
  return text;
}

TEST_F(DrawingMalformed, TruncatedGzip) {
  std::string body = kHeader;
  for (int i = 0; i < 20000; ++i) {
    body += std::to_string(1492954983454LL + 8 * i) + "," +
            std::to_string((i * 7919) % 2003 / 10.0) + "," +
            std::to_string((i * 104729) % 1999 / 10.0) + ",1,2,3,0.5,4,1," +
            std::to_string(i % 97 / 10.0) + ",0\n";
  }
  nibrig::test::write_truncated_gzip(dir_ / "pen_paper_cube.csv.gz", body, 0.5);
  expect_message_names(format_error_of([&] { read_paper_drawing(dir_ / "pen_paper_cube.csv.gz"); }),
                       {"pen_paper_cube.csv.gz", "line ", "compressed data is truncated"});
}

TEST_F(DrawingMalformed, NonNumericField) {
  const auto file =
      write(kHeader + drawing_rows(2) + "1492954983478,89.6,abc,24.8,49.8,-62.5,-0.6,295.6,0,0.2,0.1\n");
  expect_message_names(
      format_error_of([&] { read_paper_drawing(file); }),
      {"pen_paper_cube.csv.gz", "line 4, field 'Y'", "expected a number, found 'abc'"});
}

TEST_F(DrawingMalformed, NaNField) {
  const auto file =
      write(kHeader + drawing_rows(2) + "1492954983478,89.6,1,24.8,49.8,-62.5,nan,295.6,0,0.2,0.1\n");
  expect_message_names(format_error_of([&] { read_paper_drawing(file); }),
                       {"pen_paper_cube.csv.gz", "line 4, field 'F'", "expected a finite number"});
}

TEST_F(DrawingMalformed, MissingColumn) {
  const auto file = write("Unix Timestamp,X,Y,Z,Phi,Theta,F,Ground,Touch\n" + drawing_rows(2));
  expect_message_names(
      format_error_of([&] { read_paper_drawing(file); }),
      {"pen_paper_cube.csv.gz", "line 1", "missing column 'Speed'", "Unix Timestamp,X,Y"});
}

TEST_F(DrawingMalformed, EmptyFile) {
  const auto file = write("");
  expect_message_names(format_error_of([&] { read_paper_drawing(file); }),
                       {"pen_paper_cube.csv.gz", "empty file", "Unix Timestamp,X,Y"});
}

TEST_F(DrawingMalformed, UnparsableFileName) {
  const auto file = write(kHeader + drawing_rows(2), "pen_paper.csv.gz");
  expect_message_names(format_error_of([&] { read_paper_drawing(file); }),
                       {"pen_paper.csv.gz", "unparsable file name", "<tool>_<surface>_<subject>"});
}

TEST_F(DrawingMalformed, WrongSampleRate) {
  std::string body = kHeader;  // stamps 1 ms apart: 1000 Hz, not the tablet
  for (int i = 0; i < 20; ++i)
    body += std::to_string(1492954983454LL + i) + ",1,2,3,0,0,0.5,0,1,0.1,0\n";
  const auto file = write(body);
  expect_message_names(format_error_of([&] { read_paper_drawing(file); }),
                       {"pen_paper_cube.csv.gz", "column 'Unix Timestamp'", "expected about 120 Hz",
                        "found 1000.0"});
}

TEST_F(DrawingMalformed, TouchAndTimestampsAreChecked) {
  const auto touch =
      write(kHeader + drawing_rows(2) + "1492954983478,89.6,1,24.8,49.8,-62.5,0,295.6,2,0.2,0.1\n");
  expect_message_names(format_error_of([&] { read_paper_drawing(touch); }),
                       {"line 4, field 'Touch'", "expected 0 or 1, found '2'"});
  const auto repeated =
      write(kHeader + drawing_rows(2) + "1492954983462,89.6,1,24.8,49.8,-62.5,0,295.6,0,0.2,0.1\n",
            "pen_paper_cup.csv.gz");
  expect_message_names(
      format_error_of([&] { read_paper_drawing(repeated); }),
      {"pen_paper_cup.csv.gz", "line 4, field 'Unix Timestamp'", "expected time to increase"});
  const auto negative_speed =
      write(kHeader + drawing_rows(2) + "1492954983478,89.6,1,24.8,49.8,-62.5,0,295.6,0,-0.2,0\n",
            "pen_paper_ball.csv.gz");
  expect_message_names(format_error_of([&] { read_paper_drawing(negative_speed); }),
                       {"line 4, field 'Speed'", "expected a distance per frame (>= 0)"});
}

// A force of 1e308 N in a stroke was taken, and rendered: the file is held to render --force's
// bound (every real recording, -1.7 to 9.4 N, is read by the test above).
TEST(PaperDrawing, AForceBeyondAPensIsRefusedNamingItsLine) {
  const auto dir = nibrig::test::scratch_dir("drawing_force");
  const std::string header = "Unix Timestamp,X,Y,Z,Phi,Theta,F,Ground,Touch,Speed,Acceeration\n";
  for (const char* force : {"1e308", "-51", "50.001"}) {
    nibrig::test::write_text(dir / "pen_paper_s.csv", header +
                                                          "1700000000000,10,40,0,0,0,1.2,0,1,0,0\n"
                                                          "1700000000008,10.3,40,0,0,0," +
                                                          force + ",0,1,0.3,0\n");
    expect_message_names(format_error_of([&] { read_paper_drawing(dir / "pen_paper_s.csv"); }),
                         {"pen_paper_s.csv", "line 3, field 'F'", "50 N", force});
  }
  nibrig::test::write_text(dir / "pen_paper_s.csv", header +
                                                        "1700000000000,10,40,0,0,0,50,0,1,0,0\n"
                                                        "1700000000008,10.3,40,0,0,0,-1.7,0,1,0.3,0\n");
  EXPECT_NO_THROW(read_paper_drawing(dir / "pen_paper_s.csv"));
}

}  // namespace
}  // namespace nibrig::model::io
