// End-to-end tests of `nibrig render`, `devices` and `audition`, each run as the built `nibrig` in a
// child process (cli_harness.hpp); the device commands run against a private JACK server with the dummy driver.
#include <gtest/gtest.h>
#include <sndfile.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
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

// The switches of an audition as its --json lists them: the tool heard from each.
std::vector<std::string> switched_to(const nlohmann::json& audition) {
  std::vector<std::string> tools;
  for (const auto& s : audition.at("switches")) tools.push_back(s.at("tool").get<std::string>());
  return tools;
}

TEST(AudioCli, DevicesAndAuditionUseTheJackServerByName) {
  nibrig::testing::JackServer server;
  const auto out = nibrig::test::scratch_dir("cli_devices");
  ASSERT_EQ(run_cli({"devices", "--json", (out / "devices.json").string()}), 0);
  const auto devices = test::read_json(out / "devices.json");
  const nlohmann::json* jack = nullptr;
  for (const auto& api : devices.at("audio"))
    if (api.at("api") == "jack") jack = &api;
  ASSERT_NE(jack, nullptr) << devices.dump(1);
  EXPECT_TRUE(jack->at("available").get<bool>());
  // The test server's dummy driver: 2 playback and 2 capture ports, at its 48 kHz.
  const nlohmann::json* found = nullptr;
  for (const auto& d : jack->at("devices"))
    if (d.at("name") == "system") found = &d;
  ASSERT_NE(found, nullptr) << devices.dump(1);
  const auto& system = *found;
  EXPECT_EQ(system.at("output_channels"), 2);
  EXPECT_EQ(system.at("input_channels"), 2);
  EXPECT_EQ(system.at("sample_rates_hz"), nlohmann::json::array({48000}));

  const auto json = out / "audition.json";
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"audition", "--tool", "cryon", "--surface", "office", "--also", "stab",
                            "--switch-every", "0.4", "--speed", "120", "--api", "jack", "--device",
                            "sys", "--seconds", "1", "--json", json.string()});
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  const auto audition = test::read_json(json);
  EXPECT_EQ(audition.at("tools"), nlohmann::json::array({"cryon", "stab"}));
  EXPECT_EQ(audition.at("stream").at("device"), "system");
  EXPECT_EQ(audition.at("stream").at("sample_rate_hz"), 48000);
  // Switches at 0.4 and 0.8 s of a 1 s run; the loop looks every 50 ms, so a loaded machine may
  // see the second late but never before its time.
  const auto tools = switched_to(audition);
  ASSERT_GE(tools.size(), 1u) << audition.dump(1);
  EXPECT_EQ(tools[0], "stab");
  EXPECT_GE(audition["switches"][0].at("at_s").get<double>(), 0.4);
  // The engine ran: callbacks of the server's periods, about a second of frames. The dummy driver
  // keeps wall time; half a second either way allows a loaded machine's late start and end.
  const auto& engine = audition.at("engine");
  EXPECT_GT(engine.at("callbacks").get<double>(), 0);
  EXPECT_NEAR(engine.at("frames").get<double>() / 48000.0, 1.0, 0.5) << engine.dump();
  EXPECT_EQ(engine.at("non_finite_samples"), 0);
  EXPECT_EQ(audition.at("device").at("losses"), 0);
}

// What audition plays reaches the device: an independent JACK client records its port while it
// switches between two tools.
TEST(AudioCli, AuditionIsHeardOnTheJackPortWhileItSwitchesTools) {
  nibrig::testing::JackServer server;
  playback::testing::JackRecorder ear("audition-ear", 1, 48000);  // 1 s
  ::testing::internal::CaptureStdout();
  const auto json = nibrig::test::scratch_dir("cli_audition_heard") / "audition.json";
  const pid_t pid =
      test::start_cli({"audition", "--tool", "cryon", "--surface", "office", "--also", "stab",
                       "--switch-every", "0.5", "--speed", "120", "--api", "jack", "--device",
                       "sys", "--seconds", "3", "--json", json.string()});
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
  // Every 0.5 s of 3 s: to stab, back to cryon, and so on (a late loop may miss the last).
  const auto tools = switched_to(test::read_json(json));
  ASSERT_GE(tools.size(), 2u) << text;
  for (std::size_t i = 0; i < tools.size(); ++i) EXPECT_EQ(tools[i], i % 2 == 0 ? "stab" : "cryon");
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
