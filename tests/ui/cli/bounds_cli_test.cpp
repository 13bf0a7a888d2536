// Issue 46 at the command line: the ranges moved into the library still name the option or file a
// user typed, say what was expected, and refuse before any work (no mesh, no fit, no file written).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;

struct Refused {
  int code = 0;
  std::string err;
};

Refused run_refused(const std::vector<std::string>& args) {
  ::testing::internal::CaptureStderr();
  Refused r;
  r.code = run_cli(args);
  r.err = ::testing::internal::GetCapturedStderr();
  return r;
}

void expect_names(const Refused& r, const std::vector<std::string>& parts) {
  EXPECT_NE(r.code, 0) << r.err;
  for (const auto& part : parts) EXPECT_NE(r.err.find(part), std::string::npos) << "no \"" << part << "\" in:\n" << r.err;
}

std::filesystem::path empty_json(const std::filesystem::path& dir) {
  std::ofstream(dir / "any.json") << "{}\n";  // a space file never read: the options fail first
  return dir / "any.json";
}

TEST(BoundsCli, ADesignsCostsAndLimitAreNamedAsTheOptions) {
  const auto dir = nibrig::test::scratch_dir("bounds_cli_design");
  const std::string space = empty_json(dir).string();
  const std::vector<std::string> base = {"design", "--target", "cryon/office", "--surface", "glass", "--space", space};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return run_refused(args);
  };
  // NaN once ran 14 s of search before failing.
  expect_names(with({"--cost", "vero=1", "--max-cost", "nan"}), {"--max-cost: nan", "expected"});
  expect_names(with({"--cost", "vero=-1"}), {"--cost of vero: -1: expected a cost proxy, 0 to 1e+15"});
  expect_names(with({"--cost", "vero=1e308"}), {"--cost of vero: 1e+308: expected a cost proxy"});
  expect_names(with({"--max-cost", "2"}), {"--max-cost limits the cost --cost gives each material"});
  // An allowed material the line does not hold is named, before the forcing model is loaded.
  expect_names(with({"--between", "vero,tip=1mm", "DM85,tip=4mm", "--allow", "steel"}),
               {"allowed steel: not a material of the line"});
}

TEST(BoundsCli, AMixShareThatPrintsAsZeroPercentIsRefusedNamingTheMaterial) {
  const auto dir = nibrig::test::scratch_dir("bounds_cli_export");
  expect_names(run_refused({"export", "DM85:1e-320,vero:1,tip=2mm", "-o", (dir / "s.3mf").string()}),
               {"DM85", "below 0.005", "0 %"});
  EXPECT_FALSE(std::filesystem::exists(dir / "s.3mf"));
}

TEST(BoundsCli, ARigsLoadAndAStrokesRangesAreNamedAsTheOptions) {
  const auto dir = nibrig::test::scratch_dir("bounds_cli_rig");
  expect_names(run_refused({"rig", "capture", "--simulated", "--tool", "cryon", "--surface", "office", "-o",
                            (dir / "s").string(), "--load", "1e308"}),
               {"--load: 1e308", "expected a load in N, 0.01 to 50"});
  EXPECT_FALSE(std::filesystem::exists(dir / "s"));
  expect_names(run_refused({"render", "--tool", "cryon", "--surface", "office", "-o", (dir / "r.wav").string(),
                            "--force", "51"}),
               {"--force: 51", "0.001 to 50"});
  expect_names(run_refused({"render", "--tool", "cryon", "--surface", "office", "-o", (dir / "r.wav").string(),
                            "--speed", "10001"}),
               {"--speed: 10001", "0.01 to 10000"});
}

TEST(BoundsCli, ADamagedPredictionIsRefusedByExportNamingTheFileAndField) {
  const auto dir = nibrig::test::scratch_dir("bounds_cli_prediction");
  // A prediction whose design repeats its tool, but whose mix share is a string: `export` read only
  // the tool before, and printed a stylus from a damaged file.
  const nlohmann::json j = {{"kind", "prediction"},
                            {"tool", "vero,tip=2mm"},
                            {"surface", "office"},
                            {"mu", "0.5"}};
  std::ofstream(dir / "damaged.json") << j.dump();
  expect_names(run_refused({"export", (dir / "damaged.json").string(), "-o", (dir / "s.3mf").string()}),
               {"damaged.json", "field 'mu'", "expected a number"});
  EXPECT_FALSE(std::filesystem::exists(dir / "s.3mf"));
}

void write_list(const std::filesystem::path& file, const std::string& rows) {
  std::ofstream(file) << "trial,stage,reference,left,right,chosen\n" << rows;
}

TEST(BoundsCli, AStageTwoStimulusNoStageOneTrialNamesIsRefusedNamingIt) {
  const auto dir = nibrig::test::scratch_dir("bounds_cli_stages");
  write_list(dir / "stage1.csv",
             "1,1,a,b,c,left\n2,1,b,c,d,right\n3,1,c,d,a,left\n4,1,d,a,b,right\n");
  write_list(dir / "stage2.csv", "1,2,a,b,c,left\n2,2,a,b,cc,right\n");  // "cc": a typo
  expect_names(run_refused({"space", "merge", (dir / "stage1.csv").string(), (dir / "stage2.csv").string(), "-o",
                            (dir / "judgments.csv").string()}),
               {"stage2.csv", "trial row 2", "unknown stimulus 'cc' in stage 2", "4 stimuli of stage 1"});
  EXPECT_FALSE(std::filesystem::exists(dir / "judgments.csv"));
  // Given in the other order, the stimuli are still stage 1's: the same refusal.
  expect_names(run_refused({"space", "merge", (dir / "stage2.csv").string(), (dir / "stage1.csv").string(), "-o",
                            (dir / "judgments.csv").string()}),
               {"stage2.csv", "unknown stimulus 'cc'"});
  // A stage-1 list with a stage-2 trial of its own, planned from: the same.
  write_list(dir / "both.csv", "1,1,a,b,c,left\n2,1,b,c,d,right\n3,1,c,d,a,left\n4,2,d,a,e,right\n");
  expect_names(run_refused({"space", "plan", (dir / "both.csv").string(), "--stage", "2", "-o",
                            (dir / "plan2.csv").string()}),
               {"both.csv", "unknown stimulus 'e' in stage 2"});
  EXPECT_FALSE(std::filesystem::exists(dir / "plan2.csv"));
  // Well-formed lists still merge.
  write_list(dir / "stage2.csv", "1,2,a,b,c,left\n2,2,a,b,c,right\n");
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"space", "merge", (dir / "stage1.csv").string(), (dir / "stage2.csv").string(), "-o",
                            (dir / "judgments.csv").string()});
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(code, 0) << out;
  EXPECT_TRUE(std::filesystem::exists(dir / "judgments.csv"));
}

}  // namespace
}  // namespace nibrig::ui::cli
