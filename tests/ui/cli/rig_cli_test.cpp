// `nibrig rig`: the commands as README gives them, a capture killed with SIGKILL and one stopped
// with Ctrl-C, and the clear lines bad requests get.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <thread>

#include "model/io/comparison_file.hpp"
#include "model/io/rig_session.hpp"
#include "playback/audio_devices.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/support/jack_server.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::test {
namespace {

// Waits (up to 60 s) until the capture record of a .partial session says `seconds` are recorded.
bool wait_for_recorded(const std::filesystem::path& partial, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    try {
      const auto json = read_json(partial / "session.json");
      if (json.contains("capture") && json["capture"]["seconds"].get<double>() >= seconds) return true;
    } catch (const std::exception&) {
      // Not written yet: the writer replaces the file atomically, so it is whole or absent.
    }
  }
  return false;
}

// A capture as a user types it, then measured as any session.
TEST(RigCli, SimulatedCaptureOfTheIssueIsASessionThatMeasureReads) {
  const auto dir = scratch_dir("rig_cli_capture");
  const auto session = dir / "vero2_office";
  ASSERT_EQ(run_cli({"rig", "capture", "--simulated", "--tool", "vero2", "--surface", "office",
                     "--profile", "sweep", "--seconds", "6", "-o", session.string()}),
            0);
  const model::io::RigSession read = model::io::read_rig_session(session);
  EXPECT_TRUE(read.complete);
  EXPECT_EQ(read.speed_m_s.size(), 6000u);
  EXPECT_EQ(read.acceleration.size(), 6u * 48000u);
  ASSERT_TRUE(read.info.capture.has_value());
  EXPECT_EQ(read.info.capture->ended_because, "profile finished");
  EXPECT_EQ(read.info.capture->dropped_frames, 0u);
  EXPECT_EQ(read.info.tool, "vero2");
  ASSERT_EQ(run_cli({"measure", session.string(), "-o", (dir / "measured.json").string()}), 0);
  const auto measured = read_json(dir / "measured.json");
  ASSERT_TRUE(measured.contains("speeds_mm_s")) << measured.dump().substr(0, 300);
  EXPECT_GE(measured["speeds_mm_s"].size(), 5u);  // the sweep covers 17-250 mm/s in 6 bins
}

// The real thing: a capture process killed with SIGKILL keeps everything up to its last block, and
// the .partial folder is measured like any session.
TEST(RigCli, CaptureKilledWithSigkillLeavesAReadableSession) {
  const auto dir = scratch_dir("rig_cli_killed");
  const auto session = dir / "killed";
  const pid_t pid = start_cli({"rig", "capture", "--simulated", "--tool", "vero2", "--surface",
                               "office", "--seconds", "60", "-o", session.string()});
  const auto partial = model::io::partial_folder_of(session);
  const bool recorded = wait_for_recorded(partial, 3.0);
  ::kill(pid, SIGKILL);
  EXPECT_EQ(wait_cli(pid), 128 + SIGKILL);
  ASSERT_TRUE(recorded) << "the capture never reported 3 s recorded";
  const model::io::RigSession read = model::io::read_rig_session(partial);
  EXPECT_FALSE(read.complete);
  EXPECT_GE(read.acceleration.size(), 3u * 48000u);
  // The streams were written block by block together: at most one 100 ms batch apart.
  const double accel_s = static_cast<double>(read.acceleration.size()) / 48000.0;
  const double speed_s = static_cast<double>(read.speed_m_s.size()) / 1000.0;
  EXPECT_NEAR(accel_s, speed_s, 0.1);
  EXPECT_EQ(read.normal_force_N.size(), read.speed_m_s.size());
  ASSERT_TRUE(read.info.capture.has_value());
  EXPECT_EQ(read.info.capture->ended_because, "");  // it never got to say
  // Past the first 2 s at rest the paper's steps begin: the kept part holds the first steps.
  EXPECT_EQ(run_cli({"measure", partial.string(), "-o", (dir / "partial.json").string()}), 0);
}

// Ctrl-C stops the motor and finishes the session with what it holds, and the exit status says it
// was interrupted (130), as for every other command.
TEST(RigCli, CaptureInterruptedFinishesItsSession) {
  const auto dir = scratch_dir("rig_cli_interrupted");
  const auto session = dir / "stopped";
  const pid_t pid = start_cli({"rig", "capture", "--simulated", "--tool", "vero2", "--surface",
                               "office", "--profile", "sweep", "--seconds", "60", "-o",
                               session.string()});
  ASSERT_TRUE(wait_for_recorded(model::io::partial_folder_of(session), 1.0));
  ::kill(pid, SIGINT);
  EXPECT_EQ(wait_cli(pid), 130);
  const model::io::RigSession read = model::io::read_rig_session(session);
  EXPECT_TRUE(read.complete);  // a finished folder, not a .partial one
  ASSERT_TRUE(read.info.capture.has_value());
  EXPECT_EQ(read.info.capture->ended_because, "interrupted");
  EXPECT_GE(read.acceleration.size(), 48000u);
  EXPECT_LT(read.acceleration.size(), 30u * 48000u);
}

TEST(RigCli, AProfileBeyondTheMotorIsRefusedWithItsRangeBeforeAnyFolder) {
  const auto dir = scratch_dir("rig_cli_too_fast");
  {
    std::ofstream profile(dir / "fast.csv");
    profile << "time_s,speed_mm_s\n0,0\n1,600\n2,600\n";
  }
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"rig", "capture", "--simulated", "--tool", "vero2", "--surface", "office",
                            "--profile", (dir / "fast.csv").string(), "-o", (dir / "s").string()});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, 1);
  EXPECT_NE(err.find("the profile asks for 600.0 mm/s; the motor follows 0-400 mm/s"),
            std::string::npos)
      << err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s.partial"));
  EXPECT_FALSE(std::filesystem::exists(dir / "s"));
}

TEST(RigCli, BadRequestsGetOneClearLine) {
  const auto dir = scratch_dir("rig_cli_bad");
  const auto out = (dir / "s").string();
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{"rig", "capture", "--tool", "vero2", "--surface", "office", "-o", out},
       2,
       "say which rig: --simulated, --usb [SERIAL] or --replay SESSION"},
      {{"rig", "capture", "--simulated", "--tool", "vero2", "-o", out},
       2,
       "--surface: the simulated rig needs a surface to simulate"},
      {{"rig", "capture", "--simulated", "--tool", "vero2", "--surface", "office", "--profile",
        "zigzag", "-o", out},
       2,
       "--profile: zigzag: expected steps, sweep or a CSV file"},
      {{"rig", "capture", "--simulated", "--tool", "vero2", "--surface", "office", "--seconds",
        "-3", "-o", out},
       2,
       "--seconds"},
      {{"rig", "capture", "--simulated", "--tool", "nope", "--surface", "office", "-o", out},
       2,
       "--tool: the bundled catalog has no vibration spectrum of tool 'nope'"},
      // No controller on this machine's bus: the line says what was looked for and what was found.
      {{"rig", "capture", "--usb", "--tool", "cryon", "--surface", "office", "-o", out},
       1,
       "no nibrig rig controller (USB 1209:000a) on the bus"},
  };
  for (const auto& c : cases) {
    ::testing::internal::CaptureStderr();
    const int code = run_cli(c.args);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(code, c.code) << c.args[3] << ": " << err;
    EXPECT_NE(err.find(c.says), std::string::npos) << err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "s.partial"));
}

// A comparison as a user types it: a report with the distance per speed, its figure, and the
// session it was measured on.
TEST(RigCli, CompareOfTheIssueWritesTheDistancePerSpeed) {
  const auto dir = scratch_dir("rig_cli_compare") / "report";
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"rig", "compare", "--simulated", "--tool", "vero2", "--surface", "office",
                            "--seconds", "6", "--report", dir.string()});
  const std::string out = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << out;
  const auto report = model::io::read_comparison_file(dir / "comparison.json");
  EXPECT_EQ(report.tool, "vero2");
  EXPECT_EQ(report.surface, "office");
  std::size_t with_rows = 0;
  for (const auto& bin : report.bins) {
    if (bin.rows == 0) continue;
    ++with_rows;
    // The same tool measured and simulated: each bin within a few dB. A bin of one or two rows is
    // a single periodogram of noise (~5.6 dB RMS by itself): only bins of 5 rows or more are held
    // to it.
    if (bin.rows >= 5) {
      EXPECT_LT(bin.lsd_db, 6.0) << bin.mean_speed_m_s;
    }
  }
  EXPECT_GE(with_rows, 10u);  // the sweep crosses the 12 bins over 17-250 mm/s
  EXPECT_LT(report.mean_lsd_db, 4.0);
  EXPECT_TRUE(is_png(dir / "comparison.png"));
  EXPECT_TRUE(model::io::read_rig_session(dir / "session").complete);
  EXPECT_FALSE(report.actuator.has_value()) << "nothing played the simulation";
}

// A design point simulated against the tool on the rig (its prediction needs the forcing model,
// fitted on the fly here) — the comparison's simulation is any tool the engine can play.
TEST(RigCli, CompareSimulatesADesignPointAgainstTheMountedTool) {
  const auto dir = scratch_dir("rig_cli_compare_design") / "report";
  ASSERT_EQ(run_cli({"rig", "compare", "--simulated", "--tool", "vero2", "--surface", "office",
                     "--design", "DM85:0.5,vero:0.5,tip=2mm", "--seconds", "3", "--speedup", "0",
                     "--report", dir.string()}),
            0);
  const auto report = model::io::read_comparison_file(dir / "comparison.json");
  EXPECT_GE(report.bins_with_rows, 6u);
  EXPECT_TRUE(std::isfinite(report.mean_lsd_db));
}

// --play: the simulated tool on an actuator (a JACK port here, recorded by an independent client)
// follows the turntable while the comparison runs.
TEST(RigCli, ComparePlaysTheSimulationOnTheActuatorThroughJack) {
  nibrig::testing::JackServer server;
  const auto dir = scratch_dir("rig_cli_compare_play") / "report";
  playback::testing::JackRecorder ear("ear", 1, 48000);
  ::testing::internal::CaptureStdout();
  const pid_t pid = start_cli({"rig", "compare", "--simulated", "--tool", "cryon", "--surface",
                               "office", "--seconds", "3", "--play", "--api", "jack", "--report",
                               dir.string()});
  // The command's output port appears once its stream is open: after the stylus is meshed, which
  // takes seconds under the sanitizers.
  bool connected = false;
  for (int i = 0; i < 3000 && !connected; ++i) {
    connected = ear.connect("nibrig-rig-play:outport 0", 0);
    if (!connected) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ear.start();
  const int code = wait_cli(pid);
  const std::string out = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << out;
  ASSERT_TRUE(connected) << "the command's JACK port never appeared";
  // The actuator took the turntable's contacts: a 3 s run of ~1 kHz sensor frames on 64-frame
  // JACK blocks (1.33 ms) applies one per block that saw a new frame, well over a hundred.
  const auto report = model::io::read_comparison_file(dir / "comparison.json");
  ASSERT_TRUE(report.actuator.has_value());
  EXPECT_GT(report.actuator->contacts, 100u);
  EXPECT_LE(report.actuator->follow_mean_s, report.actuator->follow_max_s);
  EXPECT_NEAR(report.actuator->period_s, 64.0 / 48000.0, 1e-12);
  float peak = 0.0f;
  for (std::size_t i = 0; i < ear.recorded(); ++i) peak = std::max(peak, std::abs(ear.samples(0)[i]));
  EXPECT_GT(ear.recorded(), 24000u);  // at least half a second of the run was heard
  EXPECT_GT(peak, 1e-3f);             // and it was the tool, not silence
}

TEST(RigCli, DevicesListsRigControllersAndAudioInputs) {
  const auto json = scratch_dir("rig_cli_devices") / "devices.json";
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"rig", "devices", "--json", json.string()});
  const std::string out = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << out;
  // No controller on this machine's bus, no bootloader waiting; the audio APIs compiled in listed.
  const auto devices = read_json(json);
  EXPECT_EQ(devices.at("controllers"), nlohmann::json::array()) << devices.dump(1);
  EXPECT_EQ(devices.at("bootloaders"), nlohmann::json::array()) << devices.dump(1);
  EXPECT_EQ(devices.at("audio").size(), playback::compiled_apis().size()) << devices.dump(1);
}

}  // namespace
}  // namespace nibrig::test
