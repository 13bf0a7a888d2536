#include "rt/speed_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "model/io/paper_drawing.hpp"
#include "tests/support/allocation_counter.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rt {
namespace {

TEST(SpeedSource, TheSweepIsTheRigsTriangleFrom17To250MillimetresPerSecond) {
  const SweepSpeed sweep;
  // Closed form of the triangle: low at 0, high at half the period, midway at a quarter.
  EXPECT_DOUBLE_EQ(sweep.speed_at(0.0), 0.017);
  EXPECT_NEAR(sweep.speed_at(1.5), 0.250, 1e-15);
  EXPECT_NEAR(sweep.speed_at(0.75), 0.5 * (0.017 + 0.250), 1e-15);
  EXPECT_NEAR(sweep.speed_at(2.25), 0.5 * (0.017 + 0.250), 1e-15);
  EXPECT_NEAR(sweep.speed_at(3.0 * 7 + 0.4), sweep.speed_at(0.4), 1e-12);  // periodic
  // No jump anywhere: the largest step between 1 ms samples is the slope, 2·0.233/3 m/s², × 1 ms.
  double largest = 0;
  for (int k = 1; k < 6000; ++k)
    largest = std::max(largest, std::abs(sweep.speed_at(k * 1e-3) - sweep.speed_at((k - 1) * 1e-3)));
  EXPECT_NEAR(largest, 2 * 0.233 / 3 * 1e-3, 1e-9);
  EXPECT_THROW(SweepSpeed(0.2, 0.1), std::invalid_argument);
  EXPECT_THROW(ConstantSpeed(-1.0), std::invalid_argument);
  EXPECT_EQ(ConstantSpeed(0.12).speed_at(5.0), 0.12);
  EXPECT_EQ(ConstantSpeed(0.12).force_at(5.0), kReferenceNormalForce);  // the paper's load
}

TEST(SpeedSource, ATrajectoryReplaysAnArtistsRecordedSpeedWithoutAllocating) {
  const auto file = test::shared_data() / "piovarci2018" / "drawing" / "charc_paper_ball.csv.gz";
  const model::io::DrawingTrajectory drawing = model::io::read_paper_drawing(file);
  const TrajectorySpeed source(drawing);
  EXPECT_NEAR(source.duration(), drawing.time_s.back() - drawing.time_s.front(), 1e-12);
  const std::size_t before = testing::allocations_on_this_thread();
  std::size_t touching = 0;
  for (std::size_t i = 0; i < drawing.time_s.size(); ++i) {
    const double expected = drawing.touching[i] ? drawing.speed_m_s[i] : 0.0;
    const double force = drawing.touching[i] ? std::max(0.0, drawing.normal_force_N[i]) : 0.0;
    // At a frame's own time the interpolation returns that frame (up to the subtraction of the
    // start time, a few ulps of a Unix time).
    const double t = drawing.time_s[i] - drawing.time_s.front();
    EXPECT_NEAR(source.speed_at(t), expected, 1e-9) << "frame " << i;
    EXPECT_NEAR(source.force_at(t), force, 1e-9) << "frame " << i;
    touching += drawing.touching[i];
  }
  EXPECT_EQ(testing::allocations_on_this_thread(), before);
  EXPECT_GT(touching, drawing.time_s.size() / 4);  // a drawing, not an idle recording
  // Looping: one duration later the same speed.
  EXPECT_NEAR(source.speed_at(source.duration() + 0.37), source.speed_at(0.37), 1e-9);
}

}  // namespace
}  // namespace nibrig::rt
