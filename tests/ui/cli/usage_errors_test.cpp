// A command line nibrig cannot use exits 2 with one "nibrig: error:" line (as git and cmake do),
// the program's own failures exit 1, and -q leaves only errors on stderr.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;

struct Outcome {
  int code;
  std::string err;
};

Outcome run_quietly(const std::vector<std::string>& args) {
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const int code = run_cli(args);
  const std::string err = ::testing::internal::GetCapturedStderr();
  ::testing::internal::GetCapturedStdout();
  return {code, err};
}

TEST(CliUsageErrors, MisspeltCommandSuggestsTheNearest) {
  const Outcome r = run_quietly({"mesure", "x"});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("nibrig: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("did you mean 'measure'?"), std::string::npos) << r.err;
  // One line, as every error of the command line (ARCHITECTURE.md, "Conventions").
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(CliUsageErrors, MisspeltSubcommandSuggestsFromItsOwnCommand) {
  // The suggestion comes from the level the typo is at: `space`'s fit, not a top-level command.
  const Outcome r = run_quietly({"space", "fitt", "judgments.csv"});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("did you mean 'fit'?"), std::string::npos) << r.err;
}

TEST(CliUsageErrors, UnknownOptionAndBadNumberAreUsageErrors) {
  const Outcome unknown =
      run_quietly({"render", "--tool", "cryon", "--surface", "office", "--bogus"});
  EXPECT_EQ(unknown.code, 2) << unknown.err;
  EXPECT_EQ(unknown.err.rfind("nibrig: error: ", 0), 0u) << unknown.err;
  const Outcome number = run_quietly(
      {"render", "--tool", "cryon", "--surface", "office", "--speed=-5", "-o", "x.wav"});
  EXPECT_EQ(number.code, 2) << number.err;
  EXPECT_EQ(number.err.rfind("nibrig: error: --speed: -5: expected", 0), 0u) << number.err;
}

TEST(CliUsageErrors, TheProgramsOwnFailuresStayExitCodeOne) {
  // A well-formed command whose file is missing is not a usage error.
  const Outcome r = run_quietly({"measure", "/nonexistent/arm_x_y.csv.gz", "--no-plots"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("nibrig: error: ", 0), 0u) << r.err;
}

TEST(CliUsageErrors, HelpAndVersionAreNotErrors) {
  EXPECT_EQ(run_quietly({"--help"}).code, 0);
  EXPECT_EQ(run_quietly({"--version"}).code, 0);
}

// A word that is no command, with or without --help after it, is a usage error naming the word and
// the commands there are (it was "A subcommand is required", and with --help the top-level help and
// exit 0).
TEST(CliUsageErrors, AnUnknownCommandIsNamedWithTheCommandsThereAre) {
  for (const std::vector<std::string>& line : {std::vector<std::string>{"frobnicate"},
                                              std::vector<std::string>{"frobnicate", "--help"}}) {
    const Outcome r = run_quietly(line);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("'frobnicate' is not a command; the commands are: measure, catalog,"), std::string::npos)
        << r.err;
  }
  const Outcome nested = run_quietly({"space", "frob"});
  EXPECT_EQ(nested.code, 2);
  EXPECT_NE(nested.err.find("'frob' is not a space command; the commands are: fit,"), std::string::npos) << nested.err;
}

TEST(CliUsageErrors, NoGuessWhenTheWordIsNotASlip) {
  // "rendr" is one letter off "render"; "plot" (three letters off every command) and "xyz" are not
  // slips, and a guess there would mislead.
  EXPECT_NE(run_quietly({"rendr"}).err.find("did you mean 'render'?"), std::string::npos);
  for (const std::string word : {"plot", "xyz"}) {
    const Outcome r = run_quietly({word});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << word << ": " << r.err;
  }
}

TEST(CliQuiet, SilencesWarningsButNotErrors) {
  const auto dir = nibrig::test::scratch_dir("cli_quiet");
  const std::vector<std::string> render{
      "render",      "--tool",    "cryon", "--surface", "office",
      "--speed=5000", "--seconds", "0.05",  "-o",        (dir / "x.wav").string()};
  std::vector<std::string> quiet{"-q"};
  quiet.insert(quiet.end(), render.begin(), render.end());
  // The same run warns without -q (so the assertion below can fail) and is silent with it.
  EXPECT_NE(run_quietly(render).err.find("above the measured"), std::string::npos);
  const Outcome r = run_quietly(quiet);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const Outcome failing = run_quietly({"-q", "measure", "/nonexistent/arm_x_y.csv.gz"});
  EXPECT_NE(failing.err.find("nibrig: error:"), std::string::npos);
}

TEST(CliGlobalOptions, AreAcceptedAfterTheCommandToo) {
  const auto dir = nibrig::test::scratch_dir("cli_global_after");
  // The render warns above the measured speeds without -q (checked in CliQuiet above); -q after
  // the command, even after a nested one's options, silences it the same as before the command.
  std::vector<std::string> render{
      "render",      "--tool",    "cryon", "--surface", "office",
      "--speed=5000", "--seconds", "0.05",  "-o",        (dir / "x.wav").string(), "-q"};
  const Outcome quiet = run_quietly(render);
  EXPECT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "") << "-q after the command must silence the warning";
  // -j after a nested subcommand is parsed and checked like the global one.
  const Outcome threads = run_quietly({"space", "synth", "-j", "0"});
  EXPECT_EQ(threads.code, 2) << threads.err;
  EXPECT_NE(threads.err.find("--threads"), std::string::npos) << threads.err;
  // -v and -q together are still refused after the command.
  EXPECT_EQ(run_quietly({"devices", "-v", "-q"}).code, 2);
}

}  // namespace
}  // namespace nibrig::ui::cli
