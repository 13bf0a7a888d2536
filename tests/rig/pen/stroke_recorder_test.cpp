// The pen's stroke recorder: reports from a reader's thread into the paper's drawing format, read
// back with the paper's own reader.
#include "rig/pen/stroke_recorder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "model/io/paper_drawing.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig::pen {
namespace {

// A pen moving along x at 100 mm/s, reported at 133 Hz from a monotonic reading of 200 s, the tip
// down from the 5th report on; the force rises 0.01 N a report.
PenSample recorder_sample(int k) {
  PenSample s;
  s.time_s = 200.0 + k / 133.0;
  s.x_m = 0.05 + 0.1 * k / 133.0;
  s.y_m = 0.08;
  s.pressure = 0.3;
  s.tip_down = k >= 5;
  s.in_proximity = true;
  return s;
}
double recorder_force(int k) { return k >= 5 ? 0.5 + 0.01 * k : 0.0; }

void expect_recorded(const model::io::DrawingTrajectory& t, int reports) {
  ASSERT_EQ(t.time_s.size(), static_cast<std::size_t>(reports));
  for (int k = 0; k < reports; ++k) {
    const auto i = static_cast<std::size_t>(k);
    // The writer's rounding (1e-4 mm, 1e-4 N) is far inside these.
    EXPECT_NEAR(t.x_m[i], recorder_sample(k).x_m, 1e-6) << k;
    EXPECT_NEAR(t.normal_force_N[i], recorder_force(k), 1e-3) << k;
    EXPECT_EQ(t.touching[i], recorder_sample(k).tip_down) << k;
    // Stamps in whole ms: 1 ms either way.
    EXPECT_NEAR(t.time_s[i], k / 133.0, 1e-3) << k;
  }
}

TEST(StrokeRecorder, EachRecordingIsANewFileThePapersReaderReads) {
  const auto dir = nibrig::test::scratch_dir("stroke_recorder_files");
  StrokeRecorder recorder({dir / "strokes", "pen", "tablet", "Wacom Intuos S Pen"});
  recorder.add(recorder_sample(0), 0.0);  // before start(): not recorded
  EXPECT_FALSE(recorder.recording());
  const auto first = recorder.start();
  EXPECT_TRUE(recorder.recording());
  EXPECT_EQ(first.parent_path(), dir / "strokes");
  EXPECT_EQ(first.filename().string().rfind("pen_tablet_Wacom-Intuos-S-Pen-20", 0), 0u) << first;
  EXPECT_THROW(recorder.start(), std::logic_error);
  for (int k = 0; k < 200; ++k) recorder.add(recorder_sample(k), recorder_force(k));
  const auto summary = recorder.stop();
  ASSERT_TRUE(summary);
  EXPECT_EQ(summary->file, first);
  EXPECT_EQ(summary->reports, 200u);
  EXPECT_EQ(summary->rows, 200u);
  EXPECT_EQ(summary->ended_because, "stopped");
  EXPECT_TRUE(summary->kept);
  EXPECT_FALSE(recorder.stop()) << "nothing is recording any more";
  const auto t = model::io::read_paper_drawing(first);
  EXPECT_EQ(t.tool, "pen");
  EXPECT_EQ(t.surface, "tablet");
  expect_recorded(t, 200);
  // 100 mm/s is 0.752 mm a frame at 133 Hz. The reader's rate, from whole-ms stamps, is within
  // 1 ms in 1.5 s of it (0.07 mm/s) and the positions' rounding adds 0.02 mm/s: 0.2 mm/s holds
  // both.
  for (std::size_t i = 1; i < t.speed_m_s.size(); ++i) EXPECT_NEAR(t.speed_m_s[i], 0.1, 2e-4) << i;

  // Started again within the same second: a file of its own, never the first one replaced.
  const auto second = recorder.start();
  EXPECT_NE(second, first);
  for (int k = 0; k < 3; ++k) recorder.add(recorder_sample(k), recorder_force(k));
  EXPECT_EQ(recorder.stop()->rows, 3u);
  EXPECT_EQ(model::io::read_paper_drawing(first).time_s.size(), 200u);
}

// The tablet unplugged in the middle of a stroke: the reader's thread reports it, and by the time
// that call returns the file holds every report received, closed and readable.
TEST(StrokeRecorder, ATabletRemovedMidStrokeLeavesEverythingReceivedInTheFile) {
  const auto dir = nibrig::test::scratch_dir("stroke_recorder_removed");
  StrokeRecorder recorder({dir, "pen", "tablet", "emulated"});
  const auto file = recorder.start();
  constexpr int kReports = 150;
  std::thread reader([&recorder] {
    for (int k = 0; k < kReports; ++k) recorder.add(recorder_sample(k), recorder_force(k));
    recorder.tablet_removed();
    recorder.add(recorder_sample(kReports), 1.0);  // none follows in life; ignored if one did
  });
  reader.join();
  EXPECT_FALSE(recorder.recording());
  const auto t = model::io::read_paper_drawing(file);
  expect_recorded(t, kReports);
  EXPECT_TRUE(t.touching.back()) << "the tip was still down: the stroke was cut, not ended";
  const auto last = recorder.last();
  ASSERT_TRUE(last);
  EXPECT_EQ(last->ended_because, "the tablet was removed");
  EXPECT_EQ(last->reports, std::uint64_t{kReports});
  EXPECT_EQ(last->rows, std::uint64_t{kReports});
  EXPECT_FALSE(recorder.stop()) << "the removal already ended it";
}

// The reader needs two rows; a recording stopped before that is removed, and the summary says so.
TEST(StrokeRecorder, ARecordingOfFewerThanTwoRowsIsNotLeftBehind) {
  const auto dir = nibrig::test::scratch_dir("stroke_recorder_short");
  StrokeRecorder recorder({dir, "pen", "tablet", "p"});
  const auto file = recorder.start();
  recorder.add(recorder_sample(0), 0.0);
  const auto summary = recorder.stop();
  ASSERT_TRUE(summary);
  EXPECT_FALSE(summary->kept);
  EXPECT_EQ(summary->rows, 1u);
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(StrokeRecorder, AFolderThatCannotBeWrittenIsNamed) {
  const auto dir = nibrig::test::scratch_dir("stroke_recorder_unwritable");
  { std::ofstream(dir / "not_a_folder") << "x"; }
  StrokeRecorder recorder({dir / "not_a_folder" / "strokes", "pen", "tablet", "p"});
  try {
    recorder.start();
    ADD_FAILURE() << "started in a folder that cannot exist";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "not_a_folder" / "strokes").string()),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(recorder.recording());
  recorder.add(recorder_sample(0), 0.0);  // harmless
}

}  // namespace
}  // namespace nibrig::rig::pen
