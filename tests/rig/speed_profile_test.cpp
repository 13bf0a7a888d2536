#include "rig/speed_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

TEST(SpeedProfile, PaperStepsHoldSixSpeedsAfterARestAndRepeatWhole) {
  const SpeedProfile one = paper_steps();
  EXPECT_DOUBLE_EQ(one.duration_s(), 14.0);
  EXPECT_EQ(one.speed_at(1.0), 0.0);  // at rest for the first 2 s
  EXPECT_DOUBLE_EQ(one.speed_at(2.0), 0.017);  // at a step the later value holds
  EXPECT_DOUBLE_EQ(one.speed_at(3.9), 0.017);
  EXPECT_NEAR(one.speed_at(13.0), 0.250, 1e-12);
  const SpeedProfile three = paper_steps(42.0);
  EXPECT_DOUBLE_EQ(three.duration_s(), 42.0);
  EXPECT_EQ(three.speed_at(15.0), 0.0);  // the second sweep starts at rest again
  EXPECT_NEAR(three.speed_at(41.0), 0.250, 1e-12);
  // Cut in the middle of a step and of a sweep: still a valid profile ending where asked.
  const SpeedProfile cut = paper_steps(60.0);
  EXPECT_DOUBLE_EQ(cut.duration_s(), 60.0);
  EXPECT_DOUBLE_EQ(cut.speed_at(59.0), 0.017);
}

TEST(SpeedProfile, StudySweepIsATriangleOverThePapersRange) {
  const SpeedProfile sweep = study_sweep_profile(6.0);
  EXPECT_DOUBLE_EQ(sweep.speed_at(0.0), 0.017);
  EXPECT_DOUBLE_EQ(sweep.speed_at(1.5), 0.250);
  EXPECT_DOUBLE_EQ(sweep.speed_at(0.75), (0.017 + 0.250) / 2);
  EXPECT_DOUBLE_EQ(sweep.speed_at(4.5), 0.250);
  EXPECT_DOUBLE_EQ(sweep.max_speed_m_s(), 0.250);
  // Cut a third of the way down from the top (1.5 s) to the bottom (3 s).
  EXPECT_DOUBLE_EQ(study_sweep_profile(2.0).speed_at(2.0), 0.250 - (0.250 - 0.017) / 3.0);
}

TEST(SpeedProfile, RefusesPointsThatAreNotAProfile) {
  EXPECT_THROW(SpeedProfile("x", {}), std::invalid_argument);
  EXPECT_THROW(SpeedProfile("x", {{0.5, 0.1}}), std::invalid_argument);            // not from 0
  EXPECT_THROW(SpeedProfile("x", {{0, 0.1}, {1, 0.1}, {0.5, 0.1}}), std::invalid_argument);
  EXPECT_THROW(SpeedProfile("x", {{0, 0.1}, {1, -0.1}}), std::invalid_argument);  // backwards
  EXPECT_THROW(SpeedProfile("x", {{0, 0.1}, {1, 0.1}, {1, 0.2}, {1, 0.3}}), std::invalid_argument);
  EXPECT_THROW(SpeedProfile("x", {{0, std::nan("")}}), std::invalid_argument);
}

TEST(SpeedProfile, ReadsACsvFileAndNamesTheLineOfAnError) {
  const auto dir = nibrig::test::scratch_dir("speed_profile_files");
  {
    std::ofstream f(dir / "ok.csv");
    f << "# a ramp and a hold\ntime_s,speed_mm_s\n0,0\n1,100\n3,100\n";
  }
  const SpeedProfile p = read_speed_profile(dir / "ok.csv");
  EXPECT_DOUBLE_EQ(p.speed_at(0.5), 0.05);
  EXPECT_DOUBLE_EQ(p.duration_s(), 3.0);
  {
    std::ofstream f(dir / "bad.csv");
    f << "time_s,speed_mm_s\n0,0\n1,fast\n";
  }
  try {
    read_speed_profile(dir / "bad.csv");
    FAIL() << "a word for a speed was accepted";
  } catch (const model::io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("speed_mm_s"), std::string::npos) << e.what();
  }
  {
    std::ofstream f(dir / "backwards.csv");
    f << "time_s,speed_mm_s\n0,0\n2,10\n1,10\n";
  }
  EXPECT_THROW(read_speed_profile(dir / "backwards.csv"), model::io::FormatError);
}

TEST(SpeedProfile, FitToDurationRepeatsAndCuts) {
  const SpeedProfile ramp("ramp", {{0, 0.0}, {1, 0.1}});
  const SpeedProfile longer = fit_to_duration(ramp, 2.5);
  EXPECT_DOUBLE_EQ(longer.duration_s(), 2.5);
  EXPECT_DOUBLE_EQ(longer.speed_at(1.5), 0.05);  // the second repetition, halfway
  EXPECT_DOUBLE_EQ(longer.speed_at(2.5), 0.05);
  const SpeedProfile shorter = fit_to_duration(ramp, 0.5);
  EXPECT_DOUBLE_EQ(shorter.duration_s(), 0.5);
  EXPECT_DOUBLE_EQ(shorter.speed_at(0.5), 0.05);
}

// Every duration has a bound that means something (a day): 1e308 s, or a profile file's row
// "1e308,100" with --speedup 0, would fill a disk.
TEST(SpeedProfile, NothingLastsLongerThanADay) {
  const SpeedProfile ramp("ramp", {{0, 0.0}, {1, 0.1}});
  EXPECT_NO_THROW(fit_to_duration(ramp, kMaxProfileSeconds));
  for (const double seconds : {kMaxProfileSeconds * 1.001, 1e308, std::nan(""), 0.0, -1.0})
    EXPECT_THROW(fit_to_duration(ramp, seconds), std::invalid_argument) << seconds;
  EXPECT_THROW(SpeedProfile("x", {{0, 0.1}, {1e308, 0.1}}), std::invalid_argument);
  // A tiny period repeated for a day would be billions of breakpoints.
  EXPECT_THROW(fit_to_duration(SpeedProfile("x", {{0, 0.0}, {1e-6, 0.1}}), 3600.0),
               std::invalid_argument);
  const auto dir = nibrig::test::scratch_dir("speed_profile_long");
  {
    std::ofstream f(dir / "long.csv");
    f << "time_s,speed_mm_s\n0,0\n1e308,100\n";
  }
  try {
    read_speed_profile(dir / "long.csv");
    FAIL() << "a profile of 1e308 s was accepted";
  } catch (const model::io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("long.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("a day"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::rig
