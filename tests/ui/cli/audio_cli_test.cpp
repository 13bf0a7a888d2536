// End-to-end tests of `nibrig render`, `devices` and `audition`, each run as the built `nibrig` in a
// child process (cli_harness.hpp); the device commands run against a private JACK server with the dummy driver.
#include <gtest/gtest.h>
#include <sndfile.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "tests/playback/jack_recorder.hpp"
#include "tests/support/jack_server.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;

TEST(AudioCli, RenderWritesTheToolOverTheSweepToAWav) {
  const auto out = nibrig::test::scratch_dir("cli_render");
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"render", "--tool", "cryon", "--surface", "office", "--sweep",
                            "--seconds", "1", "-o", (out / "cryon.wav").string()});
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  EXPECT_NE(text.find("cryon on office"), std::string::npos) << text;
  SF_INFO info{};
  SNDFILE* f = sf_open((out / "cryon.wav").c_str(), SFM_READ, &info);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(info.frames, 48000);
  std::vector<float> x(48000);
  sf_read_float(f, x.data(), 48000);
  sf_close(f);
  double sum = 0;
  for (float v : x) sum += double{v} * v;
  // Crayon on paper is a fraction of a m/s² rms at these speeds (catalog), 0.05 output per m/s².
  EXPECT_GT(std::sqrt(sum / 48000), 1e-3);
}

TEST(AudioCli, RenderCreatesAMissingFolderAndRefusesAFolderAsOutput) {
  const auto out = nibrig::test::scratch_dir("cli_render_folders");
  std::filesystem::remove_all(out / "new");
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"render", "--tool", "cryon", "--surface", "office", "--speed", "100",
                            "--seconds", "0.2", "-o", (out / "new" / "a.wav").string()});
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << "a missing output folder is created, not an error: " << text;
  EXPECT_TRUE(std::filesystem::is_regular_file(out / "new" / "a.wav"));
  EXPECT_NE(text.find("wrote " + (out / "new" / "a.wav").string() + "\n"), std::string::npos)
      << "the confirmation every command prints: " << text;

  // An existing folder as -o is refused while parsing (exit 2, naming the option), and nothing is
  // written into or beside it.
  std::filesystem::create_directories(out / "taken");
  ::testing::internal::CaptureStderr();
  const int refused =
      run_cli({"render", "--tool", "cryon", "--surface", "office", "-o", (out / "taken").string()});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(refused, 2) << err;
  EXPECT_NE(err.find("--output"), std::string::npos) << err;
  EXPECT_NE(err.find("is a folder"), std::string::npos) << err;
  EXPECT_TRUE(std::filesystem::is_empty(out / "taken"));
  EXPECT_FALSE(std::filesystem::exists(out / "taken.partial"));
}

TEST(AudioCli, RenderNamesWhatTheCatalogHasWhenAPairingIsMissing) {
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"render", "--tool", "cryon", "--surface", "moon", "-o", "/tmp/x.wav"});
  const std::string text = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(code, 0);
  EXPECT_NE(text.find("has one on:"), std::string::npos) << text;
  EXPECT_NE(text.find("office"), std::string::npos) << text;
}

TEST(AudioCli, DevicesAndAuditionUseTheJackServerByName) {
  nibrig::testing::JackServer server;
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"devices"}), 0);
  const std::string list = ::testing::internal::GetCapturedStdout();
  EXPECT_NE(list.find("'system': 2 out, 2 in"), std::string::npos) << list;

  ::testing::internal::CaptureStdout();
  const int code = run_cli({"audition", "--tool", "cryon", "--surface", "office", "--also", "stab",
                            "--switch-every", "0.4", "--speed", "120", "--api", "jack",
                            "--device", "sys", "--seconds", "1"});
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  EXPECT_NE(text.find("now stab on office"), std::string::npos) << text;
  EXPECT_NE(text.find("engine overruns"), std::string::npos) << text;
}

// What audition plays reaches the device: an independent JACK client records its port while it
// switches between two tools.
TEST(AudioCli, AuditionIsHeardOnTheJackPortWhileItSwitchesTools) {
  nibrig::testing::JackServer server;
  playback::testing::JackRecorder ear("audition-ear", 1, 48000);  // 1 s
  ::testing::internal::CaptureStdout();
  const pid_t pid = test::start_cli({"audition", "--tool", "cryon", "--surface", "office", "--also",
                                     "stab", "--switch-every", "0.5", "--speed", "120", "--api",
                                     "jack", "--device", "sys", "--seconds", "3"});
  // The port appears once the stream is open, after the stylus's modes are solved or read.
  bool connected = false;
  for (int i = 0; i < 3000 && !connected; ++i) {
    connected = ear.connect("nibrig-audition:outport 0", 0);
    if (!connected) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ear.start();
  const int code = test::wait_cli(pid);
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  ASSERT_TRUE(connected) << "the audition's JACK port never appeared";
  EXPECT_NE(text.find("now stab on office"), std::string::npos) << text;
  EXPECT_NE(text.find("now cryon on office"), std::string::npos) << text;  // and back
  float peak = 0.0f;
  for (std::size_t i = 0; i < ear.recorded(); ++i) peak = std::max(peak, std::abs(ear.samples(0)[i]));
  EXPECT_GT(ear.recorded(), 24000u);  // at least half a second of the run was heard
  // Both tools at 120 mm/s peak near 0.1 of full scale at the default gain (as `render` writes
  // them) and silence is 0: 1e-3 tells the tools from nothing with a wide margin either side.
  EXPECT_GT(peak, 1e-3f);
}

TEST(AudioCli, AuditionSaysWhichDevicesExistWhenTheNameIsWrong) {
  nibrig::testing::JackServer server;
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"audition", "--tool", "cryon", "--surface", "office", "--api", "jack",
                            "--device", "speakers", "--seconds", "1"});
  const std::string text = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(code, 0);
  EXPECT_NE(text.find("system"), std::string::npos) << text;
}

}  // namespace
}  // namespace nibrig::ui::cli
