// Driving the panel's views without a window: an ImGui context with a built font atlas and a
// display size, frames run one by one, and the mouse moved, pressed and released between them as a
// person would (recipes.md: press on one frame, release on the next).
#pragma once

#include <functional>

#include "imgui.h"

namespace nibrig::ui::panel::testing {

class HeadlessImGui {
 public:
  HeadlessImGui(float width = 1280.0f, float height = 800.0f) {
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = {width, height};
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  }
  ~HeadlessImGui() { ImGui::DestroyContext(context_); }
  HeadlessImGui(const HeadlessImGui&) = delete;
  HeadlessImGui& operator=(const HeadlessImGui&) = delete;

  // One frame: `widgets` inside a window filling the display, as the panel draws its views.
  void frame(const std::function<void()>& widgets) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
    ImGui::Begin("test", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
    widgets();
    ImGui::End();
    ImGui::Render();
  }
  void mouse_to(ImVec2 at) { ImGui::GetIO().MousePos = at; }
  void mouse_down(bool down) { ImGui::GetIO().MouseDown[0] = down; }
  void shift(bool down) { ImGui::GetIO().KeyShift = down; }
  // Moves there, presses on one frame and releases on the next.
  void click(ImVec2 at, const std::function<void()>& widgets) {
    mouse_to(at);
    frame(widgets);
    mouse_down(true);
    frame(widgets);
    mouse_down(false);
    frame(widgets);
  }

 private:
  ImGuiContext* context_;
};

}  // namespace nibrig::ui::panel::testing
