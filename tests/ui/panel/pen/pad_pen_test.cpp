// The pad with a pen tablet plugged in: the emulated Wacom Intuos S (tests/rig/pen) found by the
// pad's own search, a stroke drawn on it sending its speed and force, the traces drawn in a real
// GLFW window on Xvfb (the README's picture of the pad), and the tablet pulled out handing the pad
// back to the mouse.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <thread>
#include <vector>

#include "model/measure/order_statistics.hpp"
#include "rig/pen/pen_clock.hpp"
#include "rig/pen/pen_force.hpp"
#include "tests/rig/pen/emulated_tablet.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "ui/panel/devices_view.hpp"
#include "ui/panel/pad_view.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

// The pad alone in the window, as the panel lays out a view.
void pad_frame(PanelWindow& window, PadView& pad, const std::filesystem::path& screenshot = {}) {
  window.begin_frame();
  ImGui::SetNextWindowPos({0, 0});
  ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
  ImGui::Begin("pad", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
  pad.draw();
  ImGui::End();
  window.end_frame(screenshot);
}

bool pad_frames_until(PanelWindow& window, PadView& pad, const std::function<bool()>& done, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    pad_frame(window, pad);
    if (done()) return true;
    std::this_thread::sleep_for(5ms);
  }
  return false;
}

TEST(PadPen, APenStrokeDrivesThePadWithItsSpeedAndForceAndUnpluggingHandsBackTheMouse) {
  UMockdevTestbed* testbed = umockdev_testbed_new();
  {
    rig::pen::testing::EmulatedTablet tablet(testbed, rig::pen::testing::wacom_intuos_s());
    WindowSettings size = testing::hidden_window();
    size.width = 1024;  // the README's pictures' size
    size.height = 640;
    PanelWindow window(size);
    PanelAudio audio{model::design::ToolSoundOptions{}};
    PadView pad(audio);
    ASSERT_TRUE(pad_frames_until(window, pad, [&] { return pad.pen().stylus() != nullptr; }, 20s)) << pad.pen().status();
    EXPECT_NE(pad.pen().status().find("Wacom Intuos S Pen"), std::string::npos) << pad.pen().status();
    EXPECT_NE(pad.pen().status().find("default pressure curve"), std::string::npos) << pad.pen().status();

    // A stroke across the tablet, 90 mm/s along a gentle curve under a pressure that rises and
    // falls, drawn at the tablet's own rate while the pad draws frames.
    const double period = 1.0 / tablet.model().report_hz;
    double t = rig::pen::pen_clock_now_s();
    tablet.proximity_in(t, 30.0, 50.0);
    std::vector<double> middle_speeds;
    double sent_force = 0.0;
    bool was_drawing = false;
    const double down = t + period;
    for (int i = 0; i < 180; ++i) {
      t = down + i * period;
      std::this_thread::sleep_for(std::chrono::duration<double>(std::max(0.0, t - rig::pen::pen_clock_now_s())));
      // Where a pen moving at 90 mm/s is when the report leaves (a frame may make it late).
      const double now = rig::pen::pen_clock_now_s();
      const double s = 1e-3 * 90.0 * (now - down);  // metres along x
      const double pressure = 0.35 + 0.2 * std::sin(M_PI * i / 180.0);
      tablet.report(now, 30.0 + 1e3 * s, 50.0 + 8.0 * std::sin(1e3 * s / 25.0), pressure);
      pad_frame(window, pad);
      // What the pad sent in the stroke's middle frames. Their median speed: on a loaded machine
      // the pen's reader thread can wait past the speed's timeout now and then, and the pad then
      // rightly sends 0 for a frame; a wrong speed is wrong in every frame.
      if (i >= 80 && i <= 100) middle_speeds.push_back(pad.speed_mm_s());
      if (i == 90) {
        sent_force = pad.force_n();
        was_drawing = pad.drawing();
      }
    }
    const double sent_speed = model::measure::median(middle_speeds);
    EXPECT_TRUE(was_drawing);
    // The path's speed: 90 mm/s along x and the curve's y on top, 90·sqrt(1 + (8/25·cos)²), from 90 to
    // 94.5 mm/s; the tablet's 0.01 mm steps over a report or two add 0.2 %.
    EXPECT_GE(sent_speed, 90.0 * 0.98);
    EXPECT_LE(sent_speed, 94.5 * 1.02);
    // The default curve at the middle's pressure (0.55 of the range; libinput takes its 1 %
    // threshold off and rescales), to the pressure's 1/4096 steps.
    const double expected_force = rig::pen::default_pressure_curve().force_n((0.55 - 0.01) / 0.99);
    EXPECT_NEAR(sent_force, expected_force, 0.02);
    tablet.report(rig::pen::pen_clock_now_s(), 30.0 + 90.0 * 180 * period, 50.0, 0.0);
    ASSERT_TRUE(pad_frames_until(window, pad, [&] { return !pad.drawing(); }, 5s));
    EXPECT_EQ(pad.speed_mm_s(), 0.0);
    EXPECT_EQ(pad.force_n(), 0.0);
    // The picture of the pad with the stroke's traces (the README's, copied from the build tree).
    const auto picture = nibrig::test::scratch_dir("pad_pen") / "panel_pad.png";
    for (int i = 0; i < 3; ++i) pad_frame(window, pad, i == 2 ? picture : std::filesystem::path());
    EXPECT_TRUE(std::filesystem::exists(picture));

    tablet.unplug();
    ASSERT_TRUE(pad_frames_until(window, pad, [&] { return pad.pen().stylus() == nullptr; }, 5s));
    EXPECT_NE(pad.pen().status().find("unplugged"), std::string::npos) << pad.pen().status();
  }
  g_object_unref(testbed);
}

TEST(DevicesViewPen, ListsTheTabletWithItsSize) {
  UMockdevTestbed* testbed = umockdev_testbed_new();
  {
    rig::pen::testing::EmulatedTablet tablet(testbed, rig::pen::testing::wacom_intuos_s());
    PanelWindow window(testing::hidden_window());
    PanelAudio audio{model::design::ToolSoundOptions{}};
    DevicesView view(audio);
    view.refresh();
    const auto deadline = std::chrono::steady_clock::now() + 30s;
    while (!view.listing() && std::chrono::steady_clock::now() < deadline) {
      window.begin_frame();
      view.draw();
      window.end_frame();
      std::this_thread::sleep_for(10ms);
    }
    ASSERT_TRUE(view.listing());
    ASSERT_EQ(view.listing()->tablets.size(), 1u) << view.listing()->tablet_problem;
    const auto& t = view.listing()->tablets[0];
    EXPECT_EQ(t.name, "Wacom Intuos S Pen");
    EXPECT_NEAR(t.width_mm, 152.0, 1e-9);  // 15200 units at 100 a millimetre
    EXPECT_NEAR(t.height_mm, 95.0, 1e-9);
  }
  g_object_unref(testbed);
}

}  // namespace
}  // namespace nibrig::ui::panel
