#include "model/io/drawing_trajectory_writer.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <fstream>
#include <functional>
#include <iterator>
#include <numbers>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "model/io/finite_output.hpp"
#include "model/io/paper_drawing.hpp"
#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

// A pen drawing a circle of 30 mm radius at 133 Hz (a Wacom tablet's report rate) with its speed
// swinging between 50 and 200 mm/s and its force between 0.5 and 1.5 N, lifted for the first and
// last 10 reports.
struct SyntheticPenStroke {
  static constexpr double kRate = 133.0, kRadius_mm = 30.0, kPeriod = 3.0;
  static constexpr double kStart_s = 5000.1234;  // a monotonic clock's reading, not 0
  static constexpr int kFrames = 400;
  static double omega() { return 2.0 * std::numbers::pi / kPeriod; }
  static double speed_mm_s(double t) { return 125.0 - 75.0 * std::cos(omega() * t); }
  static double arc_mm(double t) { return 125.0 * t - 75.0 / omega() * std::sin(omega() * t); }
  static double time(int k) { return k / kRate; }
  static DrawingFrame frame(int k) {
    const double t = time(k);
    const double angle = arc_mm(t) / kRadius_mm;
    DrawingFrame f;
    f.time_s = kStart_s + t;
    f.x_m = (100.0 + kRadius_mm * std::cos(angle)) * 1e-3;
    f.y_m = (120.0 + kRadius_mm * std::sin(angle)) * 1e-3;
    f.normal_force_N = 1.0 + 0.5 * std::sin(omega() * t);
    f.touching = k >= 10 && k < kFrames - 10;
    return f;
  }
};

constexpr WallClockOrigin kStrokeOrigin{1700000000000LL, 5000.0};

std::vector<std::vector<std::string>> csv_rows_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream split(line);
    std::string field;
    while (std::getline(split, field, ',')) fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}

std::filesystem::path write_synthetic_stroke(const std::filesystem::path& dir, int frames) {
  const auto file = dir / drawing_file_name("pen", "tablet", "synthetic");
  DrawingTrajectoryWriter writer(file, kStrokeOrigin);
  for (int k = 0; k < frames; ++k) writer.append(SyntheticPenStroke::frame(k));
  writer.close();
  return file;
}

TEST(DrawingTrajectoryWriter, SyntheticStrokeReadsBackThroughThePaperReader) {
  const auto dir = nibrig::test::scratch_dir("drawing_writer_round_trip");
  const auto file = write_synthetic_stroke(dir, SyntheticPenStroke::kFrames);
  const DrawingTrajectory t = read_paper_drawing(file);
  ASSERT_EQ(t.time_s.size(), std::size_t{SyntheticPenStroke::kFrames});
  EXPECT_EQ(t.tool, "pen");
  EXPECT_EQ(t.surface, "tablet");
  EXPECT_EQ(t.subject, "synthetic");
  EXPECT_TRUE(t.warnings.empty());
  // The stamps are whole milliseconds, so the 399 steps' total is off by at most 1 ms of ~3000:
  // 0.05 Hz at 133 Hz.
  EXPECT_NEAR(t.frame_rate_hz, SyntheticPenStroke::kRate, 0.05);
  for (int k = 0; k < SyntheticPenStroke::kFrames; ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const DrawingFrame truth = SyntheticPenStroke::frame(k);
    const auto i = static_cast<std::size_t>(k);
    // Each stamp is rounded to its millisecond, the first one too: 1 ms either way.
    EXPECT_NEAR(t.time_s[i], SyntheticPenStroke::time(k), 1e-3);
    // What the format must keep (0.001 mm, 0.001 N); the writer rounds to a tenth of that.
    EXPECT_NEAR(t.x_m[i], truth.x_m, 1e-6);
    EXPECT_NEAR(t.y_m[i], truth.y_m, 1e-6);
    EXPECT_NEAR(t.normal_force_N[i], truth.normal_force_N, 1e-3);
    EXPECT_EQ(t.touching[i], truth.touching);
    if (k == 0) {
      EXPECT_EQ(t.speed_m_s[i], 0.0) << "no frame before the first";
      continue;
    }
    // The Speed column is the chord to the previous frame; times the reader's frame rate it is the
    // mean speed over that frame. Against the exact mean (arc over the frame's time) it differs
    // by the chord's shortfall, (arc / radius)² / 24 ≤ 1.1e-4 at 1.5 mm a frame, by the rate's
    // error of at most 3.4e-4 (above), and by the positions' rounding, √2 × 1e-4 mm a frame,
    // 0.02 mm/s at 133 Hz: 0.1 % and 0.05 mm/s hold all three.
    const double mean_mm_s = (SyntheticPenStroke::arc_mm(SyntheticPenStroke::time(k)) -
                              SyntheticPenStroke::arc_mm(SyntheticPenStroke::time(k - 1))) *
                             SyntheticPenStroke::kRate;
    EXPECT_NEAR(t.speed_m_s[i] * 1e3, mean_mm_s, 0.05 + 1e-3 * mean_mm_s);
  }
}

// The Acceeration column as the authors' files have it: each frame's Speed minus the previous
// one's. Their files hold 6 significant digits (1.3e-4 mm/frame² worst seen in tracking); the
// writer's 6 decimals leave at most 1.5e-6.
TEST(DrawingTrajectoryWriter, AccelerationIsTheChangeOfSpeedPerFrameAsInThePapersFiles) {
  const auto paper =
      nibrig::test::shared_data() / "piovarci2018" / "drawing" / "charc_paper_ball.csv.gz";
  const auto dir = nibrig::test::scratch_dir("drawing_writer_acceleration");
  const auto plain = dir / "charc_paper_ball.csv";
  {
    gzFile gz = gzopen(paper.c_str(), "rb");
    ASSERT_NE(gz, nullptr);
    std::ofstream out(plain);
    char buffer[1 << 14];
    int n = 0;
    while ((n = gzread(gz, buffer, sizeof buffer)) > 0) out.write(buffer, n);
    gzclose(gz);
  }
  const auto check = [](const std::filesystem::path& file, double tolerance) {
    const auto rows = csv_rows_of(file);
    ASSERT_GT(rows.size(), 100u);
    std::size_t checked = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
      if (std::stoll(rows[i][0]) - std::stoll(rows[i - 1][0]) > 50) continue;  // a dropout
      EXPECT_NEAR(std::stod(rows[i][10]), std::stod(rows[i][9]) - std::stod(rows[i - 1][9]),
                  tolerance)
          << file << " row " << i;
      ++checked;
    }
    EXPECT_GT(checked, rows.size() / 2);
  };
  check(plain, 2e-4);
  check(write_synthetic_stroke(dir, 200), 2e-6);
  const auto rows = csv_rows_of(dir / "pen_tablet_synthetic.csv");
  EXPECT_EQ(rows[0][9], "0.000000");
  EXPECT_EQ(rows[0][10], "0.000000");
}

// An independent reference: the authors' own file (2H pencil, with 3 tracking dropouts), read,
// written again and read back.
TEST(DrawingTrajectoryWriter, APapersFileWrittenAgainReadsTheSame) {
  const auto paper =
      nibrig::test::shared_data() / "piovarci2018" / "drawing" / "p2h_paper_ball.csv.gz";
  const DrawingTrajectory original = read_paper_drawing(paper);
  const auto dir = nibrig::test::scratch_dir("drawing_writer_paper");
  const auto file = dir / drawing_file_name(original.tool, original.surface, original.subject);
  EXPECT_EQ(file.filename(), "p2h_paper_ball.csv");
  {
    DrawingTrajectoryWriter writer(file, {1492954983454LL, 0.0});
    for (std::size_t i = 0; i < original.time_s.size(); ++i) {
      DrawingFrame f;
      f.time_s = original.time_s[i];
      f.x_m = original.x_m[i];
      f.y_m = original.y_m[i];
      f.normal_force_N = original.normal_force_N[i];
      f.touching = original.touching[i];
      writer.append(f);
    }
    writer.close();
    EXPECT_EQ(writer.rows_written(), original.time_s.size());
    EXPECT_EQ(writer.merged_reports(), 0u);
  }
  const DrawingTrajectory again = read_paper_drawing(file);
  ASSERT_EQ(again.time_s.size(), original.time_s.size());
  EXPECT_EQ(again.subject, "ball");
  // The same whole-millisecond steps: the same frame rate, to the last bit.
  EXPECT_EQ(again.frame_rate_hz, original.frame_rate_hz);
  std::size_t compared = 0;
  for (std::size_t i = 0; i < again.time_s.size(); ++i) {
    SCOPED_TRACE("row " + std::to_string(i + 2));
    EXPECT_NEAR(again.time_s[i], original.time_s[i], 1e-9);
    // The authors' positions have 0.01 mm and their forces 6 significant digits: written to
    // 1e-4 mm and 1e-4 N, they come back within that rounding.
    EXPECT_NEAR(again.x_m[i], original.x_m[i], 1e-9);
    EXPECT_NEAR(again.y_m[i], original.y_m[i], 1e-9);
    EXPECT_NEAR(again.normal_force_N[i], original.normal_force_N[i], 5e-5);
    EXPECT_EQ(again.touching[i], original.touching[i]);
    // Our Speed is recomputed from the rounded positions, theirs from the tracker's own: within
    // √2 × 0.01 mm ≈ 0.014 mm a frame (paper_drawing_test.cpp). The first row and the rows after
    // a dropout follow a frame that is not in the file, whose distance only the authors had.
    if (i == 0 || original.time_s[i] - original.time_s[i - 1] > 0.050) continue;
    EXPECT_NEAR(again.speed_m_s[i], original.speed_m_s[i], 0.015e-3 * original.frame_rate_hz);
    ++compared;
  }
  // 27 of its 11,398 steps are longer than 50 ms: the rest are compared.
  EXPECT_GT(compared, original.time_s.size() * 99 / 100);
}

// A process killed mid-stroke: the file holds every row but the one still open, and reads.
TEST(DrawingTrajectoryWriter, AKilledRecorderLeavesAReadableFile) {
  const auto dir = nibrig::test::scratch_dir("drawing_writer_killed");
  const auto file = dir / drawing_file_name("pen", "tablet", "killed");
  constexpr int kWritten = 120;
  std::fflush(nullptr);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // No destructor, no close(): as a SIGKILL leaves it.
    auto* writer = new DrawingTrajectoryWriter(file, kStrokeOrigin);
    for (int k = 0; k < kWritten; ++k) writer->append(SyntheticPenStroke::frame(k));
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const DrawingTrajectory t = read_paper_drawing(file);
  ASSERT_EQ(t.time_s.size(), std::size_t{kWritten - 1});
  EXPECT_TRUE(t.warnings.empty());
  for (int k = 0; k < kWritten - 1; ++k)
    EXPECT_NEAR(t.x_m[static_cast<std::size_t>(k)], SyntheticPenStroke::frame(k).x_m, 1e-6);
}

// A disk that fills in the middle of a row (here a file-size limit, which fails a write the same
// way): the writer says so, and the part of the row that went out is taken back, so the reader
// never takes a Speed cut short for a whole number.
TEST(DrawingTrajectoryWriter, ADiskFullMidRowLeavesOnlyWholeRows) {
  const auto dir = nibrig::test::scratch_dir("drawing_writer_full");
  const auto file = dir / drawing_file_name("pen", "tablet", "full");
  // The header (66 bytes) and about 10 rows of 75 bytes, then a limit in the middle of one.
  constexpr rlim_t kLimit = 66 + 10 * 75 + 30;
  std::fflush(nullptr);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);  // the write fails with EFBIG instead of the process ending
    const rlimit limit{kLimit, kLimit};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    DrawingTrajectoryWriter writer(file, kStrokeOrigin);
    try {
      for (int k = 0; k < 100; ++k) writer.append(SyntheticPenStroke::frame(k));
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      ::_exit(message.find("cannot write the recording") != std::string::npos &&
                      message.find("cut short") == std::string::npos
                  ? 0
                  : 2);
    }
    ::_exit(1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 0) << "1: nothing failed, 2: the wrong message";
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_LT(text.size(), kLimit);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "a row cut short was left in the file";
  const DrawingTrajectory t = read_paper_drawing(file);
  EXPECT_TRUE(t.warnings.empty());
  EXPECT_GE(t.time_s.size(), 9u);
  for (std::size_t i = 0; i < t.time_s.size(); ++i)
    EXPECT_NEAR(t.x_m[i], SyntheticPenStroke::frame(static_cast<int>(i)).x_m, 1e-6);
}

// The same while the writer is still open in this process: a reader beside a live recording.
TEST(DrawingTrajectoryWriter, AnOpenRecordingReadsUpToItsOpenRow) {
  const auto dir = nibrig::test::scratch_dir("drawing_writer_open");
  DrawingTrajectoryWriter writer(dir / "pen_tablet_live.csv", kStrokeOrigin);
  for (int k = 0; k < 50; ++k) writer.append(SyntheticPenStroke::frame(k));
  EXPECT_EQ(writer.rows_written(), 49u);
  EXPECT_EQ(read_paper_drawing(dir / "pen_tablet_live.csv").time_s.size(), 49u);
  writer.close();
  EXPECT_EQ(read_paper_drawing(dir / "pen_tablet_live.csv").time_s.size(), 50u);
}

// libinput reports a tip change and the axes of one instant as separate events: one row, the
// latest state, so that the stamps increase as the reader requires.
TEST(DrawingTrajectoryWriter, ReportsOfOneMillisecondAreOneRowWithTheLatestState) {
  const auto dir = nibrig::test::scratch_dir("drawing_writer_merge");
  DrawingTrajectoryWriter writer(dir / "pen_tablet_merge.csv", kStrokeOrigin);
  DrawingFrame f = SyntheticPenStroke::frame(0);
  writer.append(f);
  f.time_s += 0.0075;
  f.x_m += 1e-3;
  writer.append(f);
  f.time_s += 0.0003;  // the tip goes down in the same millisecond
  f.touching = true;
  f.normal_force_N = 0.8;
  writer.append(f);
  f.time_s += 0.0075;
  writer.append(f);
  writer.close();
  EXPECT_EQ(writer.rows_written(), 3u);
  EXPECT_EQ(writer.merged_reports(), 1u);
  const auto rows = csv_rows_of(dir / "pen_tablet_merge.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][8], "1");
  EXPECT_EQ(rows[1][6], "0.8000");
  EXPECT_EQ(rows[1][9], "1.000000");  // 1 mm from the first row
  EXPECT_EQ(rows[2][9], "0.000000");

  EXPECT_THROW(
      {
        DrawingTrajectoryWriter late(dir / "pen_tablet_late.csv", kStrokeOrigin);
        late.append(SyntheticPenStroke::frame(5));
        late.append(SyntheticPenStroke::frame(2));
      },
      std::invalid_argument);
}

TEST(DrawingTrajectoryWriter, TiltBecomesThePensAngleFromTheNormalAndItsAzimuth) {
  const auto dir = nibrig::test::scratch_dir("drawing_writer_tilt");
  DrawingTrajectoryWriter writer(dir / "pen_tablet_tilt.csv", kStrokeOrigin);
  const double tilts[][2] = {{0, 0}, {30, 0}, {0, 30}, {45, 45}, {-20, 0}};
  for (int k = 0; k < 5; ++k) {
    DrawingFrame f = SyntheticPenStroke::frame(k);
    f.tilt_x_deg = tilts[k][0];
    f.tilt_y_deg = tilts[k][1];
    writer.append(f);
  }
  writer.close();
  const auto rows = csv_rows_of(dir / "pen_tablet_tilt.csv");
  ASSERT_EQ(rows.size(), 5u);
  const char* expected[][2] = {{"0.00", "0.00"},
                               {"30.00", "0.00"},
                               {"30.00", "90.00"},
                               {"54.74", "45.00"},
                               {"20.00", "180.00"}};
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(rows[k][4], expected[k][0]) << "Phi, row " << k;
    EXPECT_EQ(rows[k][5], expected[k][1]) << "Theta, row " << k;
    EXPECT_EQ(rows[k][3], "0.0000") << "Z: the pen's height is not known";
    EXPECT_EQ(rows[k][7], "0") << "Ground";
  }
}

TEST(DrawingTrajectoryWriter, FileNamesSplitBackIntoToolSurfaceAndSubject) {
  EXPECT_EQ(drawing_file_name("p2h", "paper", "bottle_c2"), "p2h_paper_bottle_c2.csv");
  const std::string name =
      drawing_file_name("my_tool", "office/paper", "Wacom Intuos S Pen__2026 11:27 \xc3\xa9");
  EXPECT_EQ(name, "my-tool_office-paper_Wacom-Intuos-S-Pen_2026-11-27.csv");
  const auto dir = nibrig::test::scratch_dir("drawing_writer_names");
  {
    DrawingTrajectoryWriter writer(dir / name, kStrokeOrigin);
    for (int k = 0; k < 3; ++k) writer.append(SyntheticPenStroke::frame(k));
  }
  const DrawingTrajectory t = read_paper_drawing(dir / name);
  EXPECT_EQ(t.tool, "my-tool");
  EXPECT_EQ(t.surface, "office-paper");
  EXPECT_EQ(t.subject, "Wacom-Intuos-S-Pen_2026-11-27");
  for (const auto& [tool, surface, subject, part] :
       std::vector<std::tuple<std::string, std::string, std::string, std::string>>{
           {"__", "paper", "x", "tool"},
           {"pen", "", "x", "surface"},
           {"pen", "paper", " / ", "subject"},
           {"pen", "paper", "..", "subject"}}) {
    try {
      drawing_file_name(tool, surface, subject);
      ADD_FAILURE() << "accepted " << tool << "|" << surface << "|" << subject;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  }
}

std::string writer_refusal_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& e) {
    return e.what();
  }
  ADD_FAILURE() << "nothing was refused";
  return "";
}

TEST(DrawingTrajectoryWriter, RefusesWhatCannotBeARecordingNamingIt) {
  const auto dir = nibrig::test::scratch_dir("drawing_writer_refusals");
  const auto open = [](const std::filesystem::path& file) {
    DrawingTrajectoryWriter writer(file, kStrokeOrigin);
  };
  std::filesystem::create_directories(dir / "pen_tablet_folder.csv");
  nibrig::test::expect_message_names(
      writer_refusal_of([&] { open(dir / "pen_tablet_folder.csv"); }),
      {"pen_tablet_folder.csv", "is a folder"});
  nibrig::test::write_text(dir / "pen_tablet_taken.csv", "keep me\n");
  nibrig::test::expect_message_names(writer_refusal_of([&] { open(dir / "pen_tablet_taken.csv"); }),
                                     {"pen_tablet_taken.csv", "exists already"});
  std::ifstream kept(dir / "pen_tablet_taken.csv");
  std::string line;
  std::getline(kept, line);
  EXPECT_EQ(line, "keep me");
  // A folder that cannot be made: a file stands where it would be (as root too, unlike a mode).
  nibrig::test::write_text(dir / "plain_file", "x");
  nibrig::test::expect_message_names(
      writer_refusal_of([&] { open(dir / "plain_file" / "sub" / "pen_tablet_x.csv"); }),
      {(dir / "plain_file" / "sub").string(), "cannot create the folder"});
  nibrig::test::expect_message_names(writer_refusal_of([&] { open(dir / "pen_tablet.csv"); }),
                                     {"pen_tablet.csv", "<tool>_<surface>_<subject>.csv"});
  nibrig::test::expect_message_names(writer_refusal_of([&] { open(dir / "pen_tablet_x.csv.gz"); }),
                                     {"pen_tablet_x.csv.gz", "plain text"});
  nibrig::test::expect_message_names(writer_refusal_of([&] { open(dir / "pen__x.csv"); }),
                                     {"pen__x.csv", "no empty part"});

  DrawingTrajectoryWriter writer(dir / "pen_tablet_nan.csv", kStrokeOrigin);
  writer.append(SyntheticPenStroke::frame(0));
  DrawingFrame bad = SyntheticPenStroke::frame(1);
  bad.normal_force_N = std::nan("");
  try {
    writer.append(bad);
    ADD_FAILURE() << "a NaN force was written";
  } catch (const UnwritableOutput& e) {
    nibrig::test::expect_message_names(
        e.what(), {"pen_tablet_nan.csv", "row 2", "field 'F'", "not a finite"});
  }
  writer.close();
  EXPECT_THROW(writer.append(SyntheticPenStroke::frame(2)), std::logic_error);
}

}  // namespace
}  // namespace nibrig::model::io
