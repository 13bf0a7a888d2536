#include "ui/panel/error_line.hpp"

#include <algorithm>
#include <ctime>

#include "imgui.h"

namespace nibrig::ui::panel {

namespace {

const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};

std::string clock_time(std::chrono::system_clock::time_point when) {
  const std::time_t t = std::chrono::system_clock::to_time_t(when);
  std::tm local{};
  localtime_r(&t, &local);
  char text[16];
  std::strftime(text, sizeof text, "%H:%M:%S", &local);
  return text;
}

}  // namespace

void ErrorLine::report(std::string text) {
  if (text.empty()) return;
  if (history_.empty() || history_.front().text != text) {
    history_.push_front({std::chrono::system_clock::now(), text});
    if (history_.size() > kKept) history_.pop_back();
  }
  current_ = std::move(text);
}

float ErrorLine::height(float width, int max_lines) const {
  if (current_.empty()) return 0.0f;
  const float text = ImGui::CalcTextSize(current_.c_str(), nullptr, false, width).y;
  const float cap = ImGui::GetTextLineHeightWithSpacing() * static_cast<float>(max_lines);
  return std::min(text, cap) + ImGui::GetStyle().ItemSpacing.y;
}

void ErrorLine::draw(int max_lines) const {
  if (current_.empty()) return;
  const float width = ImGui::GetContentRegionAvail().x;
  ImGui::BeginChild("error-line", {0.0f, height(width, max_lines) - ImGui::GetStyle().ItemSpacing.y});
  ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
  ImGui::TextWrapped("%s", current_.c_str());
  ImGui::PopStyleColor();
  ImGui::EndChild();
}

void ErrorLine::draw_history(bool* open) const {
  if (!*open) return;
  ImGui::SetNextWindowSize({620.0f, 320.0f}, ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Errors", open)) {
    if (history_.empty()) ImGui::TextDisabled("nothing has gone wrong");
    for (const Entry& e : history_) {
      ImGui::TextDisabled("%s", clock_time(e.when).c_str());
      ImGui::SameLine();
      ImGui::TextWrapped("%s", e.text.c_str());
    }
  }
  ImGui::End();
}

}  // namespace nibrig::ui::panel
