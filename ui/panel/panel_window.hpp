// The panel's one window: GLFW, an OpenGL 3.3 core context and Dear ImGui with its GLFW and OpenGL 3
// back ends. A frame is begin_frame(), the views' ImGui calls, end_frame(); end_frame can read the
// frame back as a PNG before it is shown (`--screenshot`, the tests, the README's pictures).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "ui/panel/key_queue.hpp"

struct GLFWwindow;
struct ImGuiIO;

namespace nibrig::ui::panel {

struct WindowSettings {
  std::string title = "nibrig-panel";
  int width = 1280;
  int height = 800;
  bool visible = true;  // a hidden window still renders (screenshots)
  bool vsync = true;
  std::filesystem::path ini_file;  // ImGui's window layout; empty: none kept
  // A frame whose draw lists are those of the frame shown is not rendered again: on a machine
  // without a GPU the rasteriser, not the widgets, is what an idle refresh costs. Screenshots
  // always render.
  bool skip_unchanged = false;
};

class PanelWindow {
 public:
  // Throws std::runtime_error saying what is missing: no display ("run it under xvfb-run -a"), no
  // OpenGL 3.3 core context.
  explicit PanelWindow(const WindowSettings& settings);
  ~PanelWindow();
  PanelWindow(const PanelWindow&) = delete;
  PanelWindow& operator=(const PanelWindow&) = delete;

  bool should_close() const;
  // Polls events and starts an ImGui frame. Key and character events reach ImGui through a
  // KeyQueue: a key pressed and released between two frames is seen down for one frame. `input`, when given, may then change what the back end
  // read from the window (mouse, keys) before ImGui sees it: scripted sessions and tests click
  // through the real window this way.
  void begin_frame(const std::function<void(ImGuiIO&)>& input = {});
  // Renders the frame; with `screenshot` non-empty, writes it there as a PNG first (throws naming
  // the file when it cannot be written). Then shows it.
  void end_frame(const std::filesystem::path& screenshot = {});
  // Frames rendered and frames skipped as unchanged (WindowSettings::skip_unchanged).
  std::size_t frames_rendered() const { return rendered_; }
  std::size_t frames_skipped() const { return skipped_; }
  // Sleeps until input arrives or `timeout_s` passes (an idle panel waits here instead of drawing);
  // true when input (or a wake()) ended the wait. The events are then handled by begin_frame.
  // Returns at once while key events wait for a frame (a tap's release held back).
  bool wait_events(double timeout_s);
  // Ends a wait_events() from any thread (a job that finished has something to show).
  static void wake();
  // The next frame renders though its draw commands are unchanged: a texture they show changed.
  static void contents_changed();
  // The smallest size the window may take: the layout is made to hold at it.
  static constexpr int kMinWidth = 800, kMinHeight = 500;
  int framebuffer_width() const;
  int framebuffer_height() const;

 private:
  GLFWwindow* window_ = nullptr;
  KeyQueue keys_;
  // ImGui's own key and character callbacks, called from begin_frame with what keys_ hands over.
  void (*imgui_key_)(GLFWwindow*, int, int, int, int) = nullptr;
  void (*imgui_char_)(GLFWwindow*, unsigned int) = nullptr;
  std::string ini_file_;  // ImGui keeps the pointer
  bool skip_unchanged_ = false;
  std::uint64_t shown_hash_ = 0;  // of the draw data on screen
  std::size_t rendered_ = 0, skipped_ = 0;
};

// Reads the current framebuffer (bottom-up in GL) and writes it top-down as an RGB PNG.
void write_framebuffer_png(const std::filesystem::path& file, int width, int height);

}  // namespace nibrig::ui::panel
