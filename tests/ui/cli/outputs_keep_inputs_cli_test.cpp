// The trial's commands that replaced a person's files through a name they wrote, typed as the trial
// typed them: each is refused, the file is as it was, and no half-written file is left.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <thread>

#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::with_coarse;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> names_in(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

struct CliRun {
  int code;
  std::string errors;
};

CliRun quietly(std::vector<std::string> args) {
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const int code = run_cli(std::move(args));
  ::testing::internal::GetCapturedStdout();
  return {code, ::testing::internal::GetCapturedStderr()};
}

// One forcing model and one prediction file for the export cases (a coarse mesh: the files' content
// is not what these tests check).
struct Prediction {
  fs::path folder, forcing, prediction;
};

const Prediction& prediction() {
  static const Prediction made = [] {
    Prediction p;
    p.folder = nibrig::test::scratch_dir("cli_outputs_keep_inputs");
    p.forcing = p.folder / "forcing.json";
    p.prediction = p.folder / "stylus" / "stylus.json";
    fs::create_directories(p.prediction.parent_path());
    const CliRun fit = quietly(with_coarse({"forcing", "fit", "-o", p.forcing.string()}));
    EXPECT_EQ(fit.code, 0) << fit.errors;
    const CliRun predicted = quietly(with_coarse({"predict", "--design", "vero,tip=2mm", "--surface", "office",
                                               "--forcing", p.forcing.string(), "-o", p.prediction.string()}));
    EXPECT_EQ(predicted.code, 0) << predicted.errors;
    return p;
  }();
  return made;
}

TEST(OutputsKeepInputsCli, AnExportsRecipeNamedOntoItsPredictionIsRefused) {
  const auto& p = prediction();
  const std::string before = bytes_of(p.prediction);
  ASSERT_FALSE(before.empty());
  const fs::path three_mf = p.prediction.parent_path() / "stylus.3mf";
  const CliRun run = quietly(with_coarse(
      {"export", p.prediction.string(), "--forcing", p.forcing.string(), "-o", three_mf.string()}));
  EXPECT_NE(run.code, 0);
  EXPECT_NE(run.errors.find("read as an input"), std::string::npos) << run.errors;
  EXPECT_EQ(bytes_of(p.prediction), before);
  EXPECT_EQ(names_in(p.prediction.parent_path()), std::vector<std::string>{"stylus.json"})
      << "no 3MF, STL or sheet of the refused set, no temporary file";
}

TEST(OutputsKeepInputsCli, AMissingPredictionFileIsSaidToBeMissing) {
  const fs::path folder = nibrig::test::scratch_dir("cli_outputs_missing");
  const CliRun run = quietly({"export", (folder / "nothere.json").string(), "-o", (folder / "s.3mf").string()});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.errors.find("nothere.json: no such file"), std::string::npos) << run.errors;
  EXPECT_EQ(run.errors.find("tip diameter"), std::string::npos) << run.errors;
  EXPECT_EQ(names_in(folder), std::vector<std::string>{});
}

TEST(OutputsKeepInputsCli, AnStlNameLinkedToTheCatalogIsNotWrittenThrough) {
  const fs::path folder = nibrig::test::scratch_dir("cli_outputs_linked");
  fs::copy_file(nibrig::test::assets_dir() / "default_catalog.json", folder / "catalog.json");
  fs::create_directories(folder / "o");
  fs::create_symlink("../catalog.json", folder / "o" / "s-body.stl");
  const std::string before = bytes_of(folder / "catalog.json");
  const CliRun run = quietly(with_coarse({"export", "vero,tip=2mm", "--catalog", (folder / "catalog.json").string(),
                                          "-o", (folder / "o" / "s.3mf").string()}));
  EXPECT_NE(run.code, 0);
  EXPECT_NE(run.errors.find("s-body.stl"), std::string::npos) << run.errors;
  EXPECT_EQ(bytes_of(folder / "catalog.json"), before);
  EXPECT_EQ(names_in(folder / "o"), std::vector<std::string>{"s-body.stl"});
}

TEST(OutputsKeepInputsCli, AForcingFitOntoItsCatalogIsRefusedBeforeFitting) {
  const fs::path folder = nibrig::test::scratch_dir("cli_outputs_forcing");
  fs::copy_file(nibrig::test::assets_dir() / "default_catalog.json", folder / "catalog.json");
  const std::string before = bytes_of(folder / "catalog.json");
  const auto start = std::chrono::steady_clock::now();
  const CliRun run = quietly({"forcing", "fit", (folder / "catalog.json").string(), "-o", (folder / "catalog.json").string()});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(run.code, 2) << run.errors;  // a usage error: the command line names it
  EXPECT_NE(run.errors.find("--output"), std::string::npos) << run.errors;
  EXPECT_EQ(bytes_of(folder / "catalog.json"), before);
  // A fit on the full mesh takes tens of seconds; a refusal while parsing takes well under 5.
  EXPECT_LT(seconds, 5.0);
}

// `-o` and `--json` on one file: the numbers would replace the model. Refused while parsing, an
// earlier file of that name kept.
TEST(OutputsKeepInputsCli, TwoOutputsOnOneFileAreRefusedBeforeTheWork) {
  const fs::path folder = nibrig::test::scratch_dir("cli_outputs_twice");
  std::ofstream(folder / "m.json") << "a person's file";
  const CliRun run =
      quietly({"forcing", "calibrate-surface", "--surface", "paperlike", "-o",
               (folder / "m.json").string(), "--json", (folder / "." / "m.json").string()});
  EXPECT_EQ(run.code, 2) << run.errors;
  EXPECT_NE(run.errors.find("--json"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("--output"), std::string::npos) << run.errors;
  EXPECT_EQ(bytes_of(folder / "m.json"), "a person's file");
  // Two names not yet made are the same file too.
  const CliRun fresh = quietly({"latency", "--json", (folder / "new.json").string(), "--json",
                                (folder / "new.json").string()});
  EXPECT_EQ(fresh.code, 2) << fresh.errors;
  EXPECT_EQ(names_in(folder), std::vector<std::string>{"m.json"});
}

TEST(OutputsKeepInputsCli, ACatalogBuildOntoARecordingItScansIsRefusedBeforeTheAnalysis) {
  const fs::path data = nibrig::test::shared_data() / "piovarci2018" / "vibration" / "arm2";
  const fs::path folder = nibrig::test::scratch_dir("cli_outputs_catalog") / "c7";
  fs::create_directories(folder);
  const fs::path recording = folder / "arm_stab_office.csv.gz";
  ASSERT_TRUE(fs::exists(data / recording.filename())) << data;
  fs::copy_file(data / recording.filename(), recording);
  const std::string before = bytes_of(recording);
  const CliRun run = quietly({"catalog", "build", folder.string(), "-o", recording.string()});
  EXPECT_NE(run.code, 0);
  EXPECT_NE(run.errors.find("arm_stab_office.csv.gz"), std::string::npos) << run.errors;
  EXPECT_EQ(run.errors.find("analysing"), std::string::npos) << "refused before the analysis";
  EXPECT_EQ(bytes_of(recording), before);
  EXPECT_EQ(names_in(folder), std::vector<std::string>{"arm_stab_office.csv.gz"});
}

TEST(OutputsKeepInputsCli, ADemoOntoAFolderWithAPersonsFilesIsRefusedAndNothingDeleted) {
  const fs::path out = nibrig::test::scratch_dir("cli_outputs_demo") / "dm_old";
  fs::create_directories(out / "mine");
  std::ofstream(out / "SUMMARY.json") << "{}";
  std::ofstream(out / "notes.txt") << "my notes";
  const CliRun run = quietly({"demo", "--only", "space", "-o", out.string()});
  EXPECT_NE(run.code, 0);
  EXPECT_NE(run.errors.find(out.string()), std::string::npos) << run.errors;
  EXPECT_EQ(bytes_of(out / "notes.txt"), "my notes");
  EXPECT_TRUE(fs::is_directory(out / "mine"));
  EXPECT_EQ(names_in(out.parent_path()), std::vector<std::string>{"dm_old"}) << "no work folder left";
}

// A full disk, made by a file size limit (the write fails as it would with no room): the new set
// must not land beside the old one.
TEST(OutputsKeepInputsCli, AnExportThatCannotFinishLeavesTheEarlierSetWhole) {
  const auto& p = prediction();
  const fs::path folder = nibrig::test::scratch_dir("cli_outputs_full");
  const std::vector<std::string> args = with_coarse(
      {"export", p.prediction.string(), "--forcing", p.forcing.string(), "-o", (folder / "s.3mf").string()});
  ASSERT_EQ(quietly(args).code, 0);
  std::map<std::string, std::string> earlier;
  for (const auto& name : names_in(folder)) earlier[name] = bytes_of(folder / name);
  ASSERT_GE(earlier.size(), 4u) << "3MF, an STL per region, recipe, sheet";
  std::size_t largest = 0;
  for (const auto& [name, bytes] : earlier) largest = std::max(largest, bytes.size());
  std::ofstream(folder / "s.json", std::ios::app) << " ";  // so that the old set can be told apart
  earlier["s.json"] += " ";

  // Half the largest: the image is cut off (PLplot does not notice); 20 KiB: the 3MF is (lib3mf's
  // own writer aborted the process there).
  for (const std::size_t bytes : {largest / 2, std::size_t{20} << 10}) {
    rlimit old_limit{};
    ::getrlimit(RLIMIT_FSIZE, &old_limit);
    rlimit limit = old_limit;
    limit.rlim_cur = bytes;
    ::signal(SIGXFSZ, SIG_IGN);  // a write past it then fails with EFBIG instead of a signal
    ::setrlimit(RLIMIT_FSIZE, &limit);
    const CliRun run = quietly(args);  // the child inherits the limit
    ::setrlimit(RLIMIT_FSIZE, &old_limit);
    ::signal(SIGXFSZ, SIG_DFL);
    EXPECT_EQ(run.code, 1) << bytes << " bytes: " << run.errors;
    EXPECT_NE(run.errors.find("cannot"), std::string::npos) << run.errors;
    std::map<std::string, std::string> after;
    for (const auto& name : names_in(folder)) after[name] = bytes_of(folder / name);
    EXPECT_TRUE(after == earlier) << bytes << " bytes: the earlier set changed or a file was left";
  }
}

// What a stopped command was making is gone; what it was told to leave (an earlier report) stays.
void expect_nothing_left_after_ctrl_c(const std::vector<std::string>& args, const fs::path& folder,
                                      const std::string& temporary_prefix,
                                      const std::vector<std::string>& kept) {
  const pid_t pid = test::start_cli(args);
  bool writing = false;  // the temporary exists: the command is making its output
  for (int i = 0; i < 1200 && !writing; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    for (const auto& entry : fs::directory_iterator(folder))
      writing = writing || entry.path().filename().string().rfind(temporary_prefix, 0) == 0;
  }
  ::kill(pid, SIGINT);
  const int code = test::wait_cli(pid);
  EXPECT_TRUE(writing) << args[0] << " never started its output";
  EXPECT_EQ(code, 128 + SIGINT) << args[0];
  EXPECT_EQ(names_in(folder), kept) << args[0];
}

TEST(OutputsKeepInputsCli, CtrlCDuringADemoLeavesNoWorkFolder) {
  const fs::path folder = nibrig::test::scratch_dir("cli_outputs_demo_stopped");
  expect_nothing_left_after_ctrl_c({"demo", "--only", "descriptors", "-o", (folder / "dm").string()}, folder,
                                   ".dm.partial-", {});
}

TEST(OutputsKeepInputsCli, CtrlCDuringARenderLeavesNoTemporaryFile) {
  const fs::path folder = nibrig::test::scratch_dir("cli_outputs_render_stopped");
  const pid_t pid = test::start_cli({"render", "--tool", "cryon", "--surface", "office", "--seconds", "3600",
                                     "-o", (folder / "r.wav").string()});
  // Wait for the temporary file: the render is then writing.
  bool writing = false;
  for (int i = 0; i < 600 && !writing; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    for (const auto& entry : fs::directory_iterator(folder))
      writing = writing || entry.path().filename().string().rfind("r.wav.tmp-", 0) == 0;
  }
  ::kill(pid, SIGINT);
  const int code = test::wait_cli(pid);
  EXPECT_TRUE(writing) << "the render never started writing";
  EXPECT_EQ(code, 128 + SIGINT);
  EXPECT_EQ(names_in(folder), std::vector<std::string>{});
}

}  // namespace
}  // namespace nibrig::ui::cli
