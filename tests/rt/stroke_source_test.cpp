#include "rt/stroke_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "model/io/paper_drawing.hpp"
#include "tests/support/allocation_counter.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rt {
namespace {

struct Block {
  std::vector<double> speed, force;
};

Block fill(StrokeSource& source, std::uint64_t first, double rate, std::size_t count) {
  Block b{std::vector<double>(count), std::vector<double>(count)};
  source.fill(first, rate, b.speed.data(), b.force.data(), count);
  return b;
}

TEST(StrokeSource, TheSweepIsTheRigsTriangleFrom17To250MillimetresPerSecond) {
  const SweepStroke sweep;
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
  EXPECT_THROW(SweepStroke(0.2, 0.1), std::invalid_argument);
  EXPECT_THROW(SweepStroke(0.017, 0.25, 3.0, -1.0), std::invalid_argument);
  EXPECT_THROW(ConstantStroke(-1.0), std::invalid_argument);
  EXPECT_THROW(ConstantStroke(0.1, std::nan("")), std::invalid_argument);
}

TEST(StrokeSource, ABlockIsTheSourceSampledOnItsOwnClock) {
  // Sample n of a block starting at `first` is the stroke at (first + n) / rate, to the bit: a
  // render in 64-frame blocks and one in 4096-frame blocks hear the same stroke.
  SweepStroke sweep(0.017, 0.250, 3.0, 1.5);
  const double rate = 8000.0;
  const Block b = fill(sweep, 11999, rate, 37);  // across the top of the triangle at 1.5 s
  for (std::size_t n = 0; n < 37; ++n) {
    EXPECT_EQ(b.speed[n], sweep.speed_at(static_cast<double>(11999 + n) / rate)) << n;
    EXPECT_EQ(b.force[n], 1.5) << n;  // the force it was given, not the paper's
  }
  ConstantStroke constant(0.12);
  const Block c = fill(constant, 5, rate, 3);
  EXPECT_EQ(c.speed, std::vector<double>(3, 0.12));
  EXPECT_EQ(c.force, std::vector<double>(3, kReferenceNormalForce));  // the paper's load
}

TEST(StrokeSource, ATrajectoryReplaysAnArtistsRecordedSpeedWithoutAllocating) {
  const auto file = nibrig::test::shared_data() / "piovarci2018" / "drawing" / "charc_paper_ball.csv.gz";
  const model::io::DrawingTrajectory drawing = model::io::read_paper_drawing(file);
  TrajectoryStroke source(drawing);
  EXPECT_NEAR(source.duration(), drawing.time_s.back() - drawing.time_s.front(), 1e-12);
  const std::size_t before = nibrig::testing::allocations_on_this_thread();
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
  // A block of 8 kHz samples across a loop's end: each sample the interpolation at its time.
  double speed[400], force[400];
  const double rate = 8000.0;
  const auto first = static_cast<std::uint64_t>(source.duration() * rate) - 200;
  source.fill(first, rate, speed, force, 400);
  EXPECT_EQ(nibrig::testing::allocations_on_this_thread(), before);
  for (std::size_t n = 0; n < 400; ++n) {
    const double t = static_cast<double>(first + n) / rate;
    EXPECT_EQ(speed[n], source.speed_at(t)) << n;
    EXPECT_EQ(force[n], source.force_at(t)) << n;
  }
  EXPECT_GT(touching, drawing.time_s.size() / 4);  // a drawing, not an idle recording
  // Looping: one duration later the same speed.
  EXPECT_NEAR(source.speed_at(source.duration() + 0.37), source.speed_at(0.37), 1e-9);
  // A constant force in place of the recorded one; the speed is the recording's still.
  const TrajectoryStroke pressed(drawing, 3.0);
  EXPECT_EQ(pressed.force_at(0.37), 3.0);
  EXPECT_EQ(pressed.speed_at(0.37), source.speed_at(0.37));
  EXPECT_THROW(TrajectoryStroke(drawing, -0.1), std::invalid_argument);
}

TEST(StrokeSource, ALiveContactRampsToTheNewestValueWithinOneBlock) {
  LiveStroke live;
  const Block silent = fill(live, 0, 8000, 4);
  EXPECT_EQ(silent.speed, std::vector<double>(4, 0.0));  // nobody touched yet
  live.aim(0.2, 2.0);
  // Linear from the value reached (0) to the newest, arriving at the block's last sample.
  const Block ramp = fill(live, 0, 8000, 4);
  for (std::size_t n = 0; n < 4; ++n) {
    EXPECT_DOUBLE_EQ(ramp.speed[n], 0.05 * static_cast<double>(n + 1)) << n;
    EXPECT_DOUBLE_EQ(ramp.force[n], 0.5 * static_cast<double>(n + 1)) << n;
  }
  const Block held = fill(live, 0, 8000, 2);  // no new value: it stays
  EXPECT_EQ(held.speed, std::vector<double>(2, 0.2));
  // A handover from a recorded stroke starts the ramp where that stroke was.
  live.start_from(0.1, 2.2);
  live.aim(0.1, 2.2);
  EXPECT_EQ(fill(live, 0, 8000, 1).speed.front(), 0.1);
}

}  // namespace
}  // namespace nibrig::rt
