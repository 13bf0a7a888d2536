// Key presses as the X server delivers them to the panel's real GLFW window (XTest, as xdotool
// sends them), a press and its release both arriving before the next frame: each counts once.
// ImGui 1.86 alone kept only "down or up" at a frame's start, so such a tap was lost (a
// participant's R missing from responses.csv, Ctrl+1 ignored, Enter in a file dialog ignored).
// Also the KeyQueue that fixes it, on its own.
#include "ui/panel/key_queue.hpp"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "imgui.h"
#include "model/study/study_results.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "tests/ui/panel/x_keys.hpp"
#include "ui/panel/experiment_view.hpp"
#include "ui/panel/file_dialog.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel {
namespace {

KeyEvent real_keys_key(int key, int action) { return {KeyEvent::Kind::key, key, 0, action, 0, 0}; }

TEST(KeyQueue, ATapBetweenTwoFramesIsDownForOneFrameAndOrderIsKept) {
  KeyQueue queue;
  // R tapped twice, then "x" typed, then Enter tapped: all before one frame.
  queue.push(real_keys_key(GLFW_KEY_R, GLFW_PRESS));
  queue.push(real_keys_key(GLFW_KEY_R, GLFW_RELEASE));
  queue.push(real_keys_key(GLFW_KEY_R, GLFW_PRESS));
  queue.push(real_keys_key(GLFW_KEY_R, GLFW_REPEAT));
  queue.push(real_keys_key(GLFW_KEY_R, GLFW_RELEASE));
  queue.push({KeyEvent::Kind::character, 0, 0, 0, 0, 'x'});
  queue.push(real_keys_key(GLFW_KEY_ENTER, GLFW_PRESS));
  queue.push(real_keys_key(GLFW_KEY_ENTER, GLFW_RELEASE));
  // What ImGui 1.86 would see at each frame's start: R down, Enter down.
  std::vector<std::pair<bool, bool>> seen;
  std::string typed;
  bool r = false, enter = false;
  const auto sink = [&](const KeyEvent& e) {
    if (e.kind == KeyEvent::Kind::character) typed += static_cast<char>(e.codepoint);
    else if (e.action != GLFW_REPEAT) (e.key == GLFW_KEY_R ? r : enter) = e.action == GLFW_PRESS;
  };
  std::size_t frames = 0;
  while (queue.waiting() > 0 && frames < 10) {
    queue.deliver(sink);
    seen.emplace_back(r, enter);
    ++frames;
  }
  // Frame 1: R down. 2: R up. 3: R down again (its repeat changes nothing). 4: R up, "x" typed,
  // Enter down (a press waits only behind its own key's change, and behind what came before it).
  // 5: Enter up. Each press was down at one frame's start.
  ASSERT_EQ(frames, 5u);
  EXPECT_EQ(seen[0], std::make_pair(true, false));
  EXPECT_EQ(seen[1], std::make_pair(false, false));
  EXPECT_EQ(seen[2], std::make_pair(true, false));
  EXPECT_EQ(seen[3], std::make_pair(false, true));
  EXPECT_EQ(seen[4], std::make_pair(false, false));
  EXPECT_EQ(typed, "x");
  // Nothing waiting: a frame hands nothing over.
  EXPECT_EQ(queue.deliver(sink), 0u);
}

// A visible window (keys go to the focused, mapped window) that the X server has focused.
WindowSettings real_keys_window() {
  WindowSettings w = testing::hidden_window();
  w.visible = true;
  return w;
}

class RealKeys : public ::testing::Test {
 protected:
  PanelWindow window{real_keys_window()};
  testing::XKeys keys;

  void SetUp() override {
    glfwFocusWindow(glfwGetCurrentContext());
    // The focus event reaches GLFW (and ImGui) in a frame.
    for (int i = 0; i < 5; ++i) frame([] {});
  }
  // One frame with `widgets` in a window filling the display, as the panel draws its views.
  void frame(const std::function<void()>& widgets) {
    window.begin_frame();
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
    ImGui::Begin("real keys", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
    widgets();
    ImGui::End();
    window.end_frame();
  }
  // Frames enough for every held-back event to reach ImGui (one change per key per frame).
  void settle(const std::function<void()>& widgets, int frames = 12) {
    for (int i = 0; i < frames; ++i) frame(widgets);
  }
};

TEST_F(RealKeys, EveryTapOfAParticipantsKeysIsInResponsesCsv) {
  const auto dir = nibrig::test::scratch_dir("panel_real_keys_experiment");
  std::ofstream(dir / "stimuli.txt") << "cryon/office\nstab/office\nvero2/office\nDM851/office\n";
  PanelAudio audio(model::design::ToolSoundOptions{});
  ExperimentView view(audio, [] { return model::design::ToolSoundOptions{}; });
  view.form().study = (dir / "study").string();
  view.form().stimuli = (dir / "stimuli.txt").string();
  view.form().participant = "P01";
  view.form().practice = 1;
  const auto draw = [&] { view.draw(); };
  view.start();
  ASSERT_EQ(view.error(), "");
  const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (view.stage() == ExperimentView::Stage::preparing && std::chrono::steady_clock::now() < until) {
    frame(draw);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(view.stage(), ExperimentView::Stage::consent) << view.error();
  view.agree(true);
  ASSERT_EQ(view.stage(), ExperimentView::Stage::trial);
  frame(draw);

  // Four trials: R tapped three times, A and B, all sent before one frame; then the answer.
  const std::vector<std::string> answers = {"1", "2", "2", "1"};
  for (const std::string& answer : answers) {
    for (const char* key : {"r", "r", "r", "a", "b"}) keys.tap(key);
    settle(draw);
    keys.tap(answer);
    settle(draw);
  }
  keys.tap("Escape");
  settle(draw);
  EXPECT_EQ(view.stage(), ExperimentView::Stage::setup) << "Esc stops the session";
  // The session's lock went with it: no P01.lock is left in the study folder.
  EXPECT_FALSE(std::filesystem::exists(dir / "study" / "participants" / "P01.lock"));

  const auto logged = model::study::read_study(dir / "study").participants.at(0).responses;
  ASSERT_EQ(logged.size(), answers.size());
  for (std::size_t i = 0; i < logged.size(); ++i) {
    EXPECT_EQ(logged[i].plays, "RRRAB") << "trial " << i + 1;
    EXPECT_EQ(logged[i].chosen, answers[i] == "1" ? model::space::Choice::left : model::space::Choice::right)
        << "trial " << i + 1;
  }
}

TEST_F(RealKeys, EnterInTheFileDialogsNameFieldTakesTheNameEveryTime) {
  const auto dir = nibrig::test::scratch_dir("panel_real_keys_dialog");
  FileDialog files;
  std::vector<std::filesystem::path> chosen;
  const auto draw = [&] { files.draw(); };
  constexpr int kTries = 9;
  for (int i = 0; i < kTries; ++i) {
    files.open("Save", FileDialog::Mode::save, {".json"}, dir,
               [&](const std::filesystem::path& f) { chosen.push_back(f); });
    settle(draw, 3);  // the dialog appears, its name field with the keyboard
    for (const char* key : {"n", "period", "j", "s", "o", "n"}) keys.tap(key);
    keys.tap("Return");
    settle(draw);
    EXPECT_FALSE(files.is_open()) << "try " << i + 1 << ": " << files.selection();
    files.cancel();
    settle(draw, 2);
  }
  ASSERT_EQ(chosen.size(), static_cast<std::size_t>(kTries));
  for (const auto& f : chosen) EXPECT_EQ(f, std::filesystem::weakly_canonical(dir / "n.json"));
}

TEST_F(RealKeys, CtrlAndADigitShowTheViewAfterADrawOnThePad) {
  const auto dir = std::filesystem::path(NIBRIG_TEST_BINARY_DIR) / "scratch" / "panel_real_keys_views";
  std::filesystem::remove_all(dir);
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  Panel panel(setup);
  const auto panel_frame = [&](const std::function<void(ImGuiIO&)>& input = {}) {
    window.begin_frame(input);
    panel.draw();
    window.end_frame();
  };
  constexpr int kTries = 6;
  int shown = 0;
  for (int i = 0; i < kTries; ++i) {
    panel.show(View::pad);
    for (int f = 0; f < 3; ++f) panel_frame();
    ASSERT_EQ(panel.current(), View::pad);
    // A stroke across the middle of the window, the button then released.
    const ImVec2 centre{window.framebuffer_width() * 0.5f, window.framebuffer_height() * 0.5f};
    for (int f = 0; f < 20; ++f)
      panel_frame([&](ImGuiIO& io) {
        io.MousePos = {centre.x - 100.0f + 10.0f * static_cast<float>(f), centre.y};
        io.MouseDown[0] = f > 0 && f < 19;
      });
    keys.press("Control_L");
    keys.tap("1");
    keys.release("Control_L");
    for (int f = 0; f < 12; ++f) panel_frame();
    if (panel.current() == View::space) ++shown;
  }
  EXPECT_EQ(shown, kTries);
}

}  // namespace
}  // namespace nibrig::ui::panel
