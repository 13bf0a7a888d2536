// The drawing reader's accepted frame rates: the paper's tracker (about 120 Hz) and the pen tablets
// whose strokes nibrig records in the same format (100-300 Hz), refusing what no tracker gives.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "model/io/paper_drawing.hpp"
#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

// `rows` rows whose stamps step by `steps_ms` in turn, moving 0.3 mm a row along x.
std::string rows_stepping(const std::vector<int>& steps_ms, int rows) {
  std::string text = "Unix Timestamp,X,Y,Z,Phi,Theta,F,Ground,Touch,Speed,Acceeration\n";
  long long stamp = 1700000000000LL;
  for (int i = 0; i < rows; ++i) {
    if (i > 0) stamp += steps_ms[static_cast<std::size_t>(i - 1) % steps_ms.size()];
    text += std::to_string(stamp) + "," + std::to_string(10.0 + 0.3 * i) + ",40,0,0,0,1.2,0,1," +
            (i == 0 ? "0" : "0.3") + ",0\n";
  }
  return text;
}

// The XP-Pen Deco 01 V2 reports every 3.76 ms: whole-ms stamps step 4, 4, 4, 3 (3.75 ms, 266.7 Hz).
TEST(PaperDrawingRates, AStrokeRecordedAt266HzIsAcceptedAtItsRate) {
  const auto dir = nibrig::test::scratch_dir("drawing_rates_266");
  nibrig::test::write_text(dir / "pen_tablet_xp-pen.csv", rows_stepping({4, 4, 4, 3}, 401));
  const DrawingTrajectory d = read_paper_drawing(dir / "pen_tablet_xp-pen.csv");
  // 400 steps over 1500 ms.
  EXPECT_DOUBLE_EQ(d.frame_rate_hz, 400.0 * 1000.0 / 1500.0);
  // 0.3 mm a frame at that rate: 80 mm/s.
  EXPECT_NEAR(d.speed_m_s[200], 0.3e-3 * d.frame_rate_hz, 1e-12);
  EXPECT_NEAR(d.speed_m_s[200], 0.080, 1e-12);
}

// Both ends of the accepted range, and each tablet's rate between them.
TEST(PaperDrawingRates, TheRangeRunsFrom30To500Hz) {
  const auto dir = nibrig::test::scratch_dir("drawing_rates_range");
  struct Case {
    std::vector<int> steps_ms;
    double rate_hz;
  };
  // 33.3 Hz (30 ms), 133.3 (the Intuos S: 7, 8), 200 (5), 500 (2).
  for (const Case& c : {Case{{30}, 1000.0 / 30.0}, Case{{7, 8}, 2000.0 / 15.0}, Case{{5}, 200.0}, Case{{2}, 500.0}}) {
    SCOPED_TRACE(c.rate_hz);
    nibrig::test::write_text(dir / "pen_tablet_rate.csv", rows_stepping(c.steps_ms, 41));
    EXPECT_NEAR(read_paper_drawing(dir / "pen_tablet_rate.csv").frame_rate_hz, c.rate_hz, 1e-9);
  }
}

// 25 Hz (40 ms steps) is slower than any tablet tracks a moving pen, and 1000 Hz (1 ms) faster;
// the message says what was expected, the range accepted and what was found.
TEST(PaperDrawingRates, RatesOutsideTheRangeAreRefusedNamingTheRange) {
  const auto dir = nibrig::test::scratch_dir("drawing_rates_refused");
  nibrig::test::write_text(dir / "pen_tablet_slow.csv", rows_stepping({40}, 20));
  expect_message_names(format_error_of([&] { read_paper_drawing(dir / "pen_tablet_slow.csv"); }),
                       {"pen_tablet_slow.csv", "column 'Unix Timestamp'", "a pen tablet's 100-300 Hz",
                        "30-500 Hz accepted", "found 25.0"});
  nibrig::test::write_text(dir / "pen_tablet_fast.csv", rows_stepping({1}, 20));
  expect_message_names(format_error_of([&] { read_paper_drawing(dir / "pen_tablet_fast.csv"); }),
                       {"pen_tablet_fast.csv", "30-500 Hz accepted", "found 1000.0"});
}

}  // namespace
}  // namespace nibrig::model::io
