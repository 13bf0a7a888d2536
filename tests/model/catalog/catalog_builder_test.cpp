#include "model/catalog/catalog_builder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <set>

#include "model/io/bundled_assets.hpp"
#include "model/measure/threshold_curve.hpp"
#include "model/numeric/cancellation.hpp"

#include "tests/support/test_paths.hpp"

namespace nibrig::model::catalog {
namespace {

std::size_t count_files(const std::filesystem::path& folder, const std::string& prefix) {
  std::size_t n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(folder)) {
    const auto name = e.path().filename().string();
    if (e.is_regular_file() && name.rfind(prefix, 0) == 0 && name.find(".csv") != std::string::npos)
      ++n;
  }
  return n;
}

TEST(FindRecordings, FindsEveryFrictionAndVibrationFileOfThePaper) {
  const auto root = nibrig::test::shared_data() / "piovarci2018";
  const auto found = find_recordings(root);
  std::size_t friction = 0, vibration = 0;
  for (const auto& f : found.files) {
    if (f.kind == RecordingKind::paper_friction) ++friction;
    if (f.kind == RecordingKind::paper_vibration) ++vibration;
  }
  // Independent count straight from the file system: every friction CSV, every arm_ CSV.
  std::size_t friction_on_disk = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root / "friction")) {
    if (e.is_regular_file()) ++friction_on_disk;
  }
  EXPECT_EQ(friction, friction_on_disk);
  EXPECT_EQ(vibration, count_files(root / "vibration", "arm_"));
  // The only skipped file is the bare timestamp list; drawings are not rig recordings.
  ASSERT_EQ(found.skipped.size(), 1u);
  EXPECT_NE(found.skipped[0].find("ts.csv.gz"), std::string::npos);
}

TEST(ClassifyRecording, RejectsWhatIsNotARecordingWithItsPath) {
  const auto dir = nibrig::test::scratch_dir("classify");
  try {
    classify_recording(dir / "nothing.csv");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nothing.csv"), std::string::npos);
  }
  try {
    classify_recording(dir);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("session.json"), std::string::npos);
  }
}

// A progress that stops the build (Ctrl-C in Python, an exception its callback raised) reaches the
// caller as that exception, from whichever worker saw it; it used to leave a worker thread and end
// the process ("terminate called after throwing ... Cancelled").
TEST(BuildCatalog, WhatTheProgressThrowsStopsTheBuildAndReachesTheCaller) {
  const auto found = find_recordings(nibrig::test::shared_data() / "piovarci2018" / "vibration");
  ASSERT_GT(found.files.size(), 4u);
  const auto threshold = measure::ThresholdCurve::load(io::default_threshold_curve());
  std::atomic<int> reports{0};
  EXPECT_THROW(build_catalog(found, threshold, AnalysisOptions{}, 2,
                             [&](const std::filesystem::path&) {
                               ++reports;
                               throw numeric::Cancelled("catalog build");
                             }),
               numeric::Cancelled);
  // Each of the two workers stops at its first report: the rest of the 75 files are not analysed.
  EXPECT_LE(reports.load(), 2);
}

}  // namespace
}  // namespace nibrig::model::catalog
