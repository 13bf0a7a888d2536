// The round trip on a JACK server's dummy driver, where nothing played comes back: the bar fills
// with the time the impulses take (it had stayed empty for the whole 12 s of one period), and once
// done the section says why none was found and what to connect.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "tests/support/jack_server.hpp"
#include "tests/ui/panel/headless_imgui.hpp"
#include "ui/panel/round_trip_section.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

TEST(RoundTripHint, OnTheDummyDriverTheBarFillsWithTimeAndTheSectionSaysWhyNothingCameBack) {
  nibrig::testing::JackServer server;  // the dummy driver: no loopback
  testing::HeadlessImGui imgui;
  RoundTripSection section;
  RoundTripRequest request;
  request.periods = {64};
  request.impulses = 12;
  request.interval_ms = 100.0;  // 1.2 s of impulses in the one period
  section.set_request(request);
  const DeviceRequest output{"jack", "system", 1, 64};
  section.start(output);
  ASSERT_TRUE(section.running()) << section.error();
  double last = 0.0, most = 0.0;
  bool never_fell = true;
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (section.running() && std::chrono::steady_clock::now() < deadline) {
    imgui.frame([&] { section.draw(output); });
    if (!section.running()) break;  // done: the bar is gone
    const double shown = section.shown_progress();
    never_fell &= shown >= last;
    last = shown;
    most = std::max(most, shown);
    std::this_thread::sleep_for(20ms);
  }
  ASSERT_FALSE(section.running());
  EXPECT_TRUE(never_fell);
  // One period reports only at its end: without the time the bar stayed at 0 until then. The
  // impulses take 1.2 s of the run, so by their end the bar is past half (0.95 at most: an estimate).
  EXPECT_GT(most, 0.5);
  EXPECT_LE(most, 0.95 + 1e-9);
  ASSERT_EQ(section.results().size(), 1u) << section.error();
  EXPECT_EQ(section.results()[0].stats.found, 0u);
  EXPECT_EQ(section.results()[0].stats.played, 12u);
  const std::string hint = section.hint();
  EXPECT_NE(hint.find("No impulse came back"), std::string::npos) << hint;
  EXPECT_NE(hint.find("input channel 1"), std::string::npos) << hint;
  EXPECT_NE(hint.find("dummy driver"), std::string::npos) << hint;
}

}  // namespace
}  // namespace nibrig::ui::panel
