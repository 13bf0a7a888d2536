// The devices view's round trip in a real window on Xvfb with a real JACK server whose loopback
// driver (jackd -L) RtAudio lists as the device `loopback`: a click on the button measures on a
// background job while frames go on, and the table shows the figures the measurement found.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/jack_server.hpp"
#include "tests/ui/panel/windowed_panel.hpp"
#include "ui/panel/devices_view.hpp"
#include "ui/panel/panel.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

TEST(PanelRoundTrip, TheDevicesViewMeasuresOnAJobAndShowsTheFigures) {
  nibrig::testing::JackServer server({48000, 128, 2});
  testing::WindowedPanel s(testing::small_space_on_jack("panel_round_trip"));
  s.panel.show(View::devices);
  ASSERT_TRUE(s.frames_until([&] { return s.panel.settled(); }, 60s));
  DevicesView& view = s.panel.devices_view();
  // The output the form names; the input is the same device's first channel.
  view.set_request(DeviceRequest{"jack", "loopback", 1, 128});
  RoundTripRequest request;
  request.periods = {128};
  request.impulses = 10;
  request.interval_ms = 100.0;
  view.round_trip().set_request(request);
  s.frame();
  ASSERT_TRUE(view.round_trip().measure_button().has_value());
  s.click(*view.round_trip().measure_button());
  ASSERT_TRUE(view.measuring()) << view.round_trip().error();

  // Ten impulses 100 ms apart take over a second: a frame that waited for them would be that long.
  // Frames on llvmpipe take tens of milliseconds, so half a second says the UI never waited.
  double longest_frame_s = 0.0;
  int frames = 0;
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (view.measuring() && std::chrono::steady_clock::now() < deadline) {
    const auto start = std::chrono::steady_clock::now();
    s.frame();
    longest_frame_s =
        std::max(longest_frame_s,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    ++frames;
  }
  ASSERT_FALSE(view.measuring()) << "the measurement did not end within 60 s";
  EXPECT_GT(frames, 10);
  EXPECT_LT(longest_frame_s, 0.5);
  s.frame();
  ASSERT_EQ(view.round_trip().error(), "");
  const auto& results = view.round_trip().results();
  ASSERT_EQ(results.size(), 1u);
  const auto& r = results[0];
  EXPECT_EQ(r.stream.device, "loopback");

  // One cycle in the loopback driver and one period in RtAudio's JACK back end: 256 frames
  // (round_trip_run_test). An xrun may hand a block a cycle late or spoil it: with xruns, up to one
  // impulse of ten missing or a period later, the mean then within 12.8 frames.
  if (r.xruns == 0) {
    EXPECT_EQ(r.stats.found, 10u);
    EXPECT_EQ(r.stats.mean_samples, 256.0);
  } else {
    EXPECT_GE(r.stats.found, 9u);
    EXPECT_GE(r.stats.mean_samples, 256.0);
    EXPECT_LE(r.stats.mean_samples, 256.0 + 12.8);
  }
  // The table shows those figures: device, period, found, mean, sd, worst (ms), mean and worst
  // (frames) and xruns.
  const auto& rows = view.round_trip().shown_rows();
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_EQ(rows[0].size(), 8u);
  EXPECT_EQ(rows[0][0], "jack 'loopback'");
  EXPECT_EQ(rows[0][1], "128");
  EXPECT_EQ(rows[0][2], std::to_string(r.stats.found) + "/10");
  char mean[32];
  std::snprintf(mean, sizeof mean, "%.3f", r.mean_ms);
  EXPECT_EQ(rows[0][3], mean);
  if (r.xruns == 0) {
    EXPECT_EQ(rows[0][3], "5.333");
  }
  if (r.xruns == 0) {
    EXPECT_EQ(rows[0][6], "256.0, 256");
  }
  EXPECT_EQ(rows[0][7], std::to_string(r.xruns));
  // The view as a person sees it, kept beside the test's other output for a look.
  const auto picture = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" /
                       "panel_round_trip" / "devices_round_trip.png";
  s.window.begin_frame();
  s.panel.draw();
  s.window.end_frame(picture);
  EXPECT_TRUE(std::filesystem::is_regular_file(picture));
}

TEST(PanelRoundTrip, APeriodThatIsNotANumberIsSaidWithoutStartingAJob) {
  EXPECT_EQ(parse_periods("64, 128,256"), (std::vector<unsigned>{64, 128, 256}));
  try {
    parse_periods("64, x");
    FAIL() << "a period that is not a number was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("periods: 'x'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_periods("0"), std::invalid_argument);
  EXPECT_THROW(parse_periods(""), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::ui::panel
