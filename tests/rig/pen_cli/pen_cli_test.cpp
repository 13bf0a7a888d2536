// `nibrig devices`, `audition --pen` and `pen calibrate` as typed, the tablet an emulated Wacom
// Intuos S in this process's umockdev testbed, which the `nibrig` child reaches through the
// inherited preload (tests/rig/pen/run_under_umockdev.sh), the audio the tests' JACK server.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "model/io/paper_drawing.hpp"
#include "rig/pen/pen_clock.hpp"
#include "rig/pen/pen_force_file.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/rig/pen/emulated_tablet.hpp"
#include "tests/support/jack_server.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::rig::pen {
namespace {

using namespace std::chrono_literals;

std::filesystem::path pen_cli_scratch(const std::string& name) {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / "pen_cli" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void sleep_until_s(double t) {
  std::this_thread::sleep_for(std::chrono::duration<double>(std::max(0.0, t - pen_clock_now_s())));
}

// Waits until the command's output (a file) holds `text`, as a person waits for a prompt.
bool wait_for_prompt(const std::filesystem::path& output, const std::string& text, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    std::ifstream in(output);
    const std::string said((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (said.find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

class PenCli : public ::testing::Test {
 protected:
  void SetUp() override {
    testbed_ = umockdev_testbed_new();
    tablet_ = std::make_unique<testing::EmulatedTablet>(testbed_, testing::wacom_intuos_s());
  }
  void TearDown() override {
    tablet_.reset();
    g_object_unref(testbed_);
  }
  // A stroke at `speed_mm_s` under `pressure`, in real time, each report stamped when written.
  void stroke(double seconds, double speed_mm_s, double pressure) {
    const double period = 1.0 / tablet_->model().report_hz;
    const double start = pen_clock_now_s();
    tablet_->proximity_in(start, 30.0, 50.0);
    for (double t = start + period; t < start + period + seconds; t += period) {
      sleep_until_s(t);
      const double now = pen_clock_now_s();
      tablet_->report(now, 30.0 + speed_mm_s * (now - start - period), 50.0, pressure);
    }
    tablet_->report(pen_clock_now_s(), 30.0 + speed_mm_s * seconds, 50.0, 0.0);
    std::this_thread::sleep_for(std::chrono::duration<double>(period));
    tablet_->proximity_out(pen_clock_now_s());
  }

  // The pen held still at `pressure` (with a hand's ±0.2 % tremor) for `seconds`, in real time.
  void hold(double pressure, double seconds) {
    const double period = 1.0 / tablet_->model().report_hz;
    const double start = pen_clock_now_s();
    for (double t = start; t < start + seconds; t += period) {
      sleep_until_s(t);
      const double tremor = 0.002 * pressure * std::sin(2 * M_PI * 6.0 * (t - start));
      tablet_->report(pen_clock_now_s(), 60.0, 40.0, pressure + tremor);
    }
  }

  UMockdevTestbed* testbed_ = nullptr;
  std::unique_ptr<testing::EmulatedTablet> tablet_;
};

TEST_F(PenCli, DevicesListsTheTabletWithItsSize) {
  const auto json = pen_cli_scratch("devices") / "devices.json";
  ::testing::internal::CaptureStdout();
  const int code = test::run_cli({"devices", "--json", json.string()});
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  const auto devices = test::read_json(json);
  ASSERT_EQ(devices.at("tablets").size(), 1u) << devices.dump(1);
  const auto& tablet = devices["tablets"][0];
  EXPECT_EQ(tablet.at("name"), "Wacom Intuos S Pen");
  EXPECT_EQ(tablet.at("model"), "Wacom Intuos S");  // libwacom's, told apart by the USB id
  EXPECT_EQ(tablet.at("devnode"), "/dev/input/event5");
  // The active area libwacom gives for the CTL-4100 (152 x 95 mm), through its inch figures.
  EXPECT_NEAR(tablet.at("width_mm").get<double>(), 152.0, 0.5) << tablet.dump();
  EXPECT_NEAR(tablet.at("height_mm").get<double>(), 95.0, 0.5) << tablet.dump();
  EXPECT_TRUE(tablet.at("pressure").get<bool>());
  EXPECT_FALSE(tablet.at("tilt").get<bool>());
  EXPECT_TRUE(devices.at("unreadable_reason").is_null());
}

TEST_F(PenCli, AuditionFollowsThePenAndRecordsItsStroke) {
  nibrig::testing::JackServer server;
  const auto folder = pen_cli_scratch("audition");
  playback::testing::JackRecorder ear("pen-ear", 1, 48000);
  ::testing::internal::CaptureStdout();
  const auto json = pen_cli_scratch("audition_json") / "audition.json";
  const pid_t pid = test::start_cli({"audition", "--pen", "intuos", "--tool", "cryon", "--surface",
                                     "office", "--api", "jack", "--device", "sys", "--seconds", "4",
                                     "--record", folder.string(), "--json", json.string()});
  // The port appears once the stream is open, after the pen is.
  bool connected = false;
  for (int i = 0; i < 3000 && !connected; ++i) {
    connected = ear.connect("nibrig-audition:outport 0", 0);
    if (!connected) std::this_thread::sleep_for(20ms);
  }
  ear.start();
  if (connected) stroke(0.6, 120.0, 0.5);
  const int code = test::wait_cli(pid);
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  ASSERT_TRUE(connected) << "the audition's JACK port never appeared\n" << text;
  // One stroke, begun and ended by the tip, played through the default curve (none stored).
  const auto pen = test::read_json(json).at("pen");
  EXPECT_EQ(pen.at("strokes"), 1) << pen.dump(1);
  const auto& events = pen.at("stroke_events");
  ASSERT_EQ(events.size(), 2u) << pen.dump(1);
  EXPECT_EQ(events[0].at("stroke"), 1);
  EXPECT_EQ(events[0].at("event"), "began");
  EXPECT_EQ(events[1].at("stroke"), 1);
  EXPECT_EQ(events[1].at("event"), "ended");
  EXPECT_EQ(events[1].at("why"), "tip up");
  // The stroke lasted the 0.6 s drawn; a loaded machine may read either end a few reports late.
  const double began = events[0].at("at_s").get<double>();
  EXPECT_GT(began, 0.0) << "the stroke was drawn after the audition began";
  EXPECT_NEAR(events[1].at("at_s").get<double>() - began, 0.6, 0.1) << pen.dump(1);
  EXPECT_TRUE(pen.at("pressure_curve").is_null());
  EXPECT_GT(pen.at("contacts").get<double>(), 50) << pen.dump(1);  // 0.6 s of 133 Hz reports
  EXPECT_FALSE(pen.at("tablet_removed").get<bool>());
  // The stroke was heard: the tool at 120 mm/s peaks near 0.1 of full scale; silence is 0.
  float peak = 0.0f;
  for (std::size_t i = 0; i < ear.recorded(); ++i) peak = std::max(peak, std::abs(ear.samples(0)[i]));
  EXPECT_GT(peak, 1e-3f);
  // The recording reads back as the paper's drawings do, at the speed drawn: the reader's speed is
  // mm per frame times its frame-rate estimate; the tablet's 0.01 mm steps over 7.5 ms frames and
  // the stamps' microsecond rounding keep the mean within 2 %.
  std::filesystem::path file;
  for (const auto& e : std::filesystem::directory_iterator(folder)) file = e.path();
  ASSERT_FALSE(file.empty()) << text;
  const auto drawing = model::io::read_paper_drawing(file);
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 2; i + 2 < drawing.speed_m_s.size(); ++i) {
    if (!drawing.touching[i] || !drawing.touching[i - 1]) continue;
    sum += drawing.speed_m_s[i];
    ++n;
  }
  ASSERT_GT(n, 50) << "tip-down rows in " << file;
  EXPECT_NEAR(sum / n, 0.120, 0.120 * 0.02);
}

// `pen calibrate` run as a person at the keyboard would: its keys through a FIFO, its output in a
// file to wait on for its first prompt; the pen store a scratch folder of its own.
class CalibrateSession {
 public:
  CalibrateSession(const std::string& name, std::vector<std::string> args, const std::string& first_prompt)
      : folder_(pen_cli_scratch(name)), said_(folder_ / "said.txt") {
    setenv("NIBRIG_PENS", folder_.c_str(), 1);
    const auto keys = folder_ / "keys";
    if (mkfifo(keys.c_str(), 0600) != 0) throw std::runtime_error("cannot make the keys' FIFO");
    // Opened for writing before the child opens it for reading: posix_spawn's child opens its
    // input before the parent runs on, and a FIFO's open waits for the other end.
    keys_ = ::open(keys.c_str(), O_RDWR | O_CLOEXEC);
    args.insert(args.begin(), {"pen", "calibrate"});
    pid_ = test::start_cli(args, keys, said_);
    unsetenv("NIBRIG_PENS");
    // The first prompt comes once the tablet is open (what was pending then, libinput threw away).
    asked_ = wait_for_prompt(said_, first_prompt, 60s);
  }
  ~CalibrateSession() {
    if (keys_ >= 0) ::close(keys_);
  }
  bool asked() const { return asked_; }
  // Enter pressed while the pen holds, as a person does: when the command does not take the hold
  // ("not taken ... again": on a loaded machine the reader may not have passed on the last reports
  // yet) the hold is made again and Enter pressed again, up to four times. True once the command
  // says `next` (its next prompt, or the curve).
  bool enter_until(const std::string& next, const std::function<void()>& hold_again) {
    for (int attempt = 0; attempt < 4; ++attempt) {
      const std::size_t refusals = count("not taken");
      if (::write(keys_, "\n", 1) != 1) throw std::runtime_error("cannot press Enter");
      const auto deadline = std::chrono::steady_clock::now() + 20s;
      while (std::chrono::steady_clock::now() < deadline) {
        if (count(next) > 0) return true;
        if (count("not taken") > refusals) break;
        std::this_thread::sleep_for(20ms);
      }
      if (count(next) > 0) return true;
      hold_again();
    }
    return false;
  }
  // The exit code, once the keys end; `said` gets what it printed.
  int finish(std::string& said) {
    ::close(keys_);
    keys_ = -1;
    const int code = test::wait_cli(pid_);
    std::ifstream in(said_);
    said.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return code;
  }
  PenCalibration stored(const std::string& file) const { return read_pen_file(folder_ / file); }
  // How often the command has said `text` so far.
  std::size_t count(const std::string& text) const {
    std::ifstream in(said_);
    const std::string said((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t n = 0;
    for (auto at = said.find(text); at != std::string::npos; at = said.find(text, at + 1)) ++n;
    return n;
  }

 private:
  std::filesystem::path folder_, said_;
  int keys_ = -1;
  pid_t pid_ = 0;
  bool asked_ = false;
};

TEST_F(PenCli, CalibrateMeasuresTheCurveFromLoadsHeldAndStoresIt) {
  CalibrateSession session("calibrate", {"--name", "test pen", "--load", "100g", "--load", "200g", "--load", "400g"},
                           "load 1 of 3");
  ASSERT_TRUE(session.asked()) << "the command never asked for the first load";
  // Each load held at its pressure for 0.8 s (longer than the 0.5 s window averaged), with a hand's
  // tremor of ±0.2 % (well inside the 5 % a steady hold allows), Enter pressed while it holds.
  const double pressures[] = {0.20, 0.38, 0.70};
  tablet_->proximity_in(pen_clock_now_s(), 60.0, 40.0);
  const char* next[] = {"load 2 of 3", "load 3 of 3", "pressure curve"};
  for (int i = 0; i < 3; ++i) {
    hold(pressures[i], 0.8);
    ASSERT_TRUE(session.enter_until(next[i], [&] { hold(pressures[i], 0.8); })) << "load " << i + 1 << " never taken";
  }
  std::string said;
  ASSERT_EQ(session.finish(said), 0) << said;
  const auto calibration = session.stored("test_pen.json");
  const auto& points = calibration.curve.points();
  ASSERT_EQ(points.size(), 4u);  // (0, 0 N) and the three loads
  const double loads_n[] = {0.1 * 9.80665, 0.2 * 9.80665, 0.4 * 9.80665};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(points[i + 1].force_n, loads_n[i], 1e-9);
    // libinput's normalised pressure of the level held: libinput takes its tip threshold (1 % of
    // the range here) off and rescales, (p - 0.01) / 0.99, which stays within 0.01 of p.
    EXPECT_NEAR(points[i + 1].pressure, pressures[i], 0.01);
  }
}

}  // namespace
}  // namespace nibrig::rig::pen
