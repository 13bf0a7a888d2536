// Every numeric option of every command refuses a meaningless value (NaN, infinity, a sign or a
// zero that means nothing, a unit slip) while the command line is parsed, naming the option, and
// values outside what the paper measured are played with a warning that says what happens.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;

struct Row {
  std::string command;  // words split at spaces; FILE and OUT are replaced by scratch paths
  std::string option;   // the option the refusal must name
};

std::ostream& operator<<(std::ostream& os, const Row& row) { return os << row.command; }

// Each row puts one bad value into a command line that is otherwise complete, so that the only
// thing wrong is the value.
const std::vector<Row> kRows = {
    {"--threads=0 devices", "--threads"},
    {"--threads=nan devices", "--threads"},
    {"--threads=-1 devices", "--threads"},
    {"render --tool cryon --surface office -o OUT --speed=-5", "--speed"},
    {"render --tool cryon --surface office -o OUT --speed=nan", "--speed"},
    {"render --tool cryon --surface office -o OUT --speed=inf", "--speed"},
    {"render --tool cryon --surface office -o OUT --speed 100 --force=nan", "--force"},
    {"render --tool cryon --surface office -o OUT --force=-3", "--force"},
    {"render --tool cryon --surface office -o OUT --force=inf", "--force"},
    {"render --tool cryon --surface office -o OUT --seconds=0", "--seconds"},
    {"render --tool cryon --surface office -o OUT --seconds=nan", "--seconds"},
    {"render --tool cryon --surface office -o OUT --rate=nan", "--rate"},
    {"render --tool cryon --surface office -o OUT --rate=100", "--rate"},
    {"render --tool cryon --surface office -o OUT --period=0", "--period"},
    {"render --tool cryon --surface office -o OUT --period=-1", "--period"},
    {"render --tool cryon --surface office -o OUT --seed=-1", "--seed"},
    {"audition --tool cryon --surface office --speed=-1", "--speed"},
    {"audition --tool cryon --surface office --switch-every=0", "--switch-every"},
    {"audition --tool cryon --surface office --seconds=inf", "--seconds"},
    {"audition --tool cryon --surface office --channel=0", "--channel"},
    {"audition --tool cryon --surface office --rate=0", "--rate"},
    {"audition --tool cryon --surface office --period=nan", "--period"},
    {"calibrate --name a --input-channel=0", "--input-channel"},
    {"calibrate --name a --accelerometer=nan", "--accelerometer"},
    {"calibrate --name a --accelerometer=-1", "--accelerometer"},
    {"catalog build DIR --compact=nan", "--compact"},
    {"catalog build DIR --compact=0", "--compact"},
    {"catalog build DIR --digits=1", "--digits"},
    // Millimetres typed as metres: a 21 m bar.
    {"mechanics modes --bar 210,20,2", "--bar"},
    {"mechanics modes --bar 0.21,0.02,nan", "--bar"},
    {"mechanics modes --bar 0.21,-0.02,0.002", "--bar"},
    {"mechanics modes --bar 0.21,0.02,0.002 --clamp=nan", "--clamp"},
    {"mechanics modes --bar 0.21,0.02,0.002 --mesh-size=0", "--mesh-size"},
    {"mechanics modes --bar 0.21,0.02,0.002 --modes=0", "--modes"},
    {"mechanics modes FILE --unit-scale=0", "--unit-scale"},
    {"mechanics modes FILE --tip 0,nan,0 --sensor 0,0,0", "--tip"},
    {"mechanics modes FILE --tip 0,0,0 --sensor 0,0,0 --sensor-axis inf,0,0", "--sensor-axis"},
    {"mechanics ringdown FILE --preload=nan", "--preload"},
    {"material calibrate bar --material PLA --printer prusa-mk3s -o OUT --length=nan", "--length"},
    {"material calibrate bar --material PLA --printer prusa-mk3s -o OUT --length 210", "--length"},
    {"design --target cryon/office --surface glass --space FILE --modes=0", "--modes"},
    {"design --target cryon/office --surface glass --space FILE --mesh-size=nan", "--mesh-size"},
    {"design --target cryon/office --surface glass --space FILE --runners-up=-1", "--runners-up"},
    {"predict --design vero,tip=2mm --surface glass --modes=nan", "--modes"},
    {"predict --design vero,tip=2mm --surface glass --mesh-size=-1", "--mesh-size"},
    {"forcing fit --mesh-size=inf", "--mesh-size"},
    {"forcing holdout --tip=nan", "--tip"},
    {"forcing holdout --tip=0", "--tip"},
    {"forcing holdout --material DM95 --fraction=nan", "--fraction"},
    {"forcing holdout --material DM95 --fraction=1.5", "--fraction"},
    {"space fit FILE --dims=0", "--dims"},
    {"space fit FILE --lambda=nan", "--lambda"},
    {"space fit FILE --lambda=-1", "--lambda"},
    {"space fit FILE --starts=0", "--starts"},
    {"space fit FILE --bootstrap=-1", "--bootstrap"},
    {"space fit FILE --seed=-1", "--seed"},
    {"space validate FILE --folds=1", "--folds"},
    {"space validate FILE --lambdas=0,nan", "--lambdas"},
    {"space synth --trials=0", "--trials"},
    {"space synth --stimuli=nan", "--stimuli"},
    {"space synth --budgets=100,-1", "--budgets"},
    {"space plan FILE -o OUT --fraction=nan", "--fraction"},
    {"space plan FILE -o OUT --max-triplets=-1", "--max-triplets"},
    {"space plan FILE -o OUT --stage=3", "--stage"},
    // One rule for every number: decimal, and nothing that starts a run that never ends.
    {"render --tool cryon --surface office -o OUT --seconds=0x10", "--seconds"},
    {"render --tool cryon --surface office -o OUT --seconds=1e308", "--seconds"},
    {"render --tool cryon --surface office -o OUT --force=1e-320", "--force"},
    {"render --tool cryon --surface office -o OUT --force=0x2", "--force"},
    {"render --tool cryon --surface office -o OUT --speed=1e308", "--speed"},
    {"audition --tool cryon --surface office --seconds=1e308", "--seconds"},
    {"rig capture --simulated --tool cryon --surface office -o OUT --seconds=1e308", "--seconds"},
    {"rig capture --simulated --tool cryon --surface office -o OUT --speedup=1e-320", "--speedup"},
    {"rig capture --simulated --tool cryon --surface office -o OUT --speedup=0.001", "--speedup"},
    {"rig capture --simulated --tool cryon --surface office -o OUT --load=0x10", "--load"},
    {"rig capture --simulated --tool cryon --surface office -o OUT --load=1e-320", "--load"},
    {"rig compare --simulated --tool cryon --surface office -o OUT --seconds=1e308", "--seconds"},
    {"experiment run --stimuli FILE --participant P1 --simulate FILE -o OUT --pace=1e-6", "--pace"},
    {"experiment run --stimuli FILE --participant P1 --simulate FILE -o OUT --rig-speedup=1e-320",
     "--rig-speedup"},
    {"space fit FILE --lambda=1e308", "--lambda"},
    {"measure FILE --load=1e-320", "--load"},
    {"mechanics modes FILE --tip 0,1e300,0 --sensor 0,0,0", "--tip"},
    // Issue 46: ranges the library holds every face to, still named as the option typed.
    {"design --target cryon/office --surface glass --space FILE --cost vero=1 --max-cost=nan", "--max-cost"},
    {"design --target cryon/office --surface glass --space FILE --cost vero=-1", "--cost of vero"},
    {"design --target cryon/office --surface glass --space FILE --min-tip-mm 3 --max-tip-mm 2", "--min-tip-mm"},
    {"rig capture --simulated --tool cryon --surface office -o OUT --load=1e308", "--load"},
    {"render --tool cryon --surface office -o OUT --force=1e308", "--force"},
};

std::vector<std::string> words(const std::string& command, const std::filesystem::path& dir) {
  std::vector<std::string> out;
  std::istringstream in(command);
  for (std::string word; in >> word;) {
    if (word == "FILE") word = (dir / "any.json").string();
    if (word == "OUT") word = (dir / "out").string();
    if (word == "DIR") word = dir.string();
    out.push_back(word);
  }
  return out;
}

class NumericOption : public ::testing::TestWithParam<Row> {};

TEST_P(NumericOption, IsRefusedNamingTheOptionBeforeAnyWork) {
  const auto dir = nibrig::test::scratch_dir("cli_numeric_options");
  { std::ofstream(dir / "any.json") << "{}\n"; }  // checked to exist only; never read
  const Row& row = GetParam();
  ::testing::internal::CaptureStderr();
  const int code = run_cli(words(row.command, dir));
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(code, 0) << err;
  // The check's own message, not some later failure that happens to be non-zero.
  EXPECT_NE(err.find(row.option + ": "), std::string::npos) << err;
  EXPECT_NE(err.find("expected"), std::string::npos) << err;
  // Refused before the command started: nothing was written.
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << err;
}

INSTANTIATE_TEST_SUITE_P(EveryCommand, NumericOption, ::testing::ValuesIn(kRows));

TEST(NumericOptions, RefusalSaysTheExpectedRangeAndUnit) {
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"render", "--tool", "cryon", "--surface", "office", "--speed=-5", "-o",
                            (nibrig::test::scratch_dir("cli_numeric_unit") / "x.wav").string()});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(code, 0);
  // The user needs the unit and the bound to retype it, not only that something was wrong.
  EXPECT_NE(err.find("--speed: -5: expected a speed in mm/s, 0 or 0.01 to 10000"), std::string::npos)
      << err;
}

TEST(NumericOptions, AUnitSlipInABarNamesTheDimension) {
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"mechanics", "modes", "--bar", "210,20,2"});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(code, 0);
  // Which of the three numbers is wrong, and the likely slip, so the fix is obvious.
  EXPECT_NE(err.find("--bar: 210: expected a bar length in metres"), std::string::npos) << err;
  EXPECT_NE(err.find("millimetres given as metres?"), std::string::npos) << err;
}

// Renders 0.05 s (a few blocks) so that the run is cheap; the point is what stderr says.
std::string render_warnings(const std::vector<std::string>& extra) {
  const auto dir = nibrig::test::scratch_dir("cli_numeric_warn");
  std::vector<std::string> args{"render",    "--tool", "cryon",
                                "--surface", "office", "--seconds",
                                "0.05",      "-o",     (dir / "x.wav").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const int code = run_cli(args);
  const std::string err = ::testing::internal::GetCapturedStderr();
  ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(code, 0) << err;
  EXPECT_TRUE(std::filesystem::exists(dir / "x.wav"));
  return err;
}

TEST(NumericOptions, SpeedAboveTheMeasuredRangeIsPlayedClampedWithAWarning) {
  const std::string err = render_warnings({"--speed=5000"});
  // 5 m/s, twenty times the fastest measured: the forcing holds that spectrum, and says so.
  EXPECT_NE(err.find("--speed 5000 mm/s is above the measured 17-250 mm/s"), std::string::npos)
      << err;
  EXPECT_NE(err.find("clamped"), std::string::npos) << err;
}

TEST(NumericOptions, SpeedBelowTheMeasuredRangeSaysItIsExtrapolated) {
  const std::string err = render_warnings({"--speed=5"});
  EXPECT_NE(err.find("below the measured 17-250 mm/s"), std::string::npos) << err;
}

TEST(NumericOptions, ForceAwayFromThePapersLoadSaysHowItIsScaled) {
  // 20 N is above the 4 x 2.2 N the forcing follows: clamped at 8.8 N.
  EXPECT_NE(render_warnings({"--force=20"}).find("clamped there"), std::string::npos);
  // 1 N is scaled, which the paper never measured.
  EXPECT_NE(render_warnings({"--force=1"}).find("an assumption"), std::string::npos);
}

TEST(NumericOptions, InsideTheMeasuredRangeThereIsNoWarning) {
  // The warning must not cry wolf: 100 mm/s at the paper's 2.2 N is what was measured.
  EXPECT_EQ(render_warnings({"--speed=100", "--force=2.2"}).find("warn"), std::string::npos);
}

}  // namespace
}  // namespace nibrig::ui::cli
