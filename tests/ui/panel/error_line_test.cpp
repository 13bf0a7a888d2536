// The panel's error line in a real window: a bad file's error is shown until something succeeds,
// then cleared and kept under Help > Errors with the earlier ones; a long error is wrapped to the
// window's width and scrolled past three lines rather than cut at the edge.
#include "ui/panel/error_line.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "tests/ui/panel/headless_imgui.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/panel.hpp"

namespace nibrig::ui::panel {
namespace {

TEST(ErrorLine, ALongErrorWrapsToTheWidthAndScrollsPastThreeLines) {
  testing::HeadlessImGui imgui;
  ErrorLine line;
  EXPECT_EQ(line.height(400.0f, 3), 0.0f);  // nothing to say: no room taken
  imgui.frame([&] {
    const float one = ImGui::GetTextLineHeightWithSpacing(), spacing = ImGui::GetStyle().ItemSpacing.y;
    line.report("a short error");
    const float short_height = line.height(400.0f, 3);
    EXPECT_NEAR(short_height, ImGui::GetTextLineHeight() + spacing, 0.5f);
    line.report(std::string(600, 'x') + " " + std::string(600, 'y'));
    // 1200 characters of about 7 px in 400 px: many lines, shown as three, the rest scrolled.
    EXPECT_NEAR(line.height(400.0f, 3), 3.0f * one + spacing, 0.5f);
    EXPECT_GT(ImGui::CalcTextSize(line.current().c_str(), nullptr, false, 400.0f).y, 3.0f * one);
  });
  ASSERT_EQ(line.history().size(), 2u);
  EXPECT_EQ(line.history().front().text, line.current());  // newest first
  line.clear();
  EXPECT_TRUE(line.current().empty());
  EXPECT_EQ(line.history().size(), 2u);
  for (std::size_t i = 0; i < 2 * ErrorLine::kKept; ++i) line.report("error " + std::to_string(i));
  EXPECT_EQ(line.history().size(), ErrorLine::kKept);
  EXPECT_EQ(line.history().front().text, "error " + std::to_string(2 * ErrorLine::kKept - 1));
}

TEST(ErrorLine, ASuccessClearsTheLineAndTheErrorIsKept) {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / "panel_error_line";
  std::filesystem::remove_all(dir);
  PanelWindow window(testing::hidden_window());
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  Panel panel(setup);
  const auto until = [&](const std::function<bool()>& done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!done() && std::chrono::steady_clock::now() < deadline) {
      window.begin_frame();
      panel.draw();
      window.end_frame();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return done();
  };
  ASSERT_TRUE(until([&] { return panel.settled(); }));
  ASSERT_TRUE(panel.error().empty()) << panel.error();
  const auto missing = dir / "no_such_space.json";
  panel.open_space(missing);
  ASSERT_TRUE(until([&] { return !panel.error().empty(); }));
  EXPECT_NE(panel.error().find(missing.string()), std::string::npos) << panel.error();
  const std::string failed = panel.error();
  panel.open_space(setup.space);
  ASSERT_TRUE(until([&] { return panel.settled() && panel.error().empty(); })) << panel.error();
  ASSERT_FALSE(panel.errors().history().empty());
  EXPECT_EQ(panel.errors().history().front().text, failed);
}

}  // namespace
}  // namespace nibrig::ui::panel
