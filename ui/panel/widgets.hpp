// Small widgets the views share that ImGui 1.86 lacks.
#pragma once

#include <cstdio>
#include <string>

#include "imgui.h"

namespace nibrig::ui::panel {

// Puts the next item beside the last one when `next_width` fits before the window's right edge,
// else on the next line: a row of widgets wraps in a narrow window instead of running off it.
inline void same_line_if_fits(float next_width) {
  const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + next_width;
  if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}
// The width a button labelled `label` takes; a labelled field `field_width` wide.
inline float button_width(const char* label) {
  return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}
inline float labelled_width(const char* label, float field_width) {
  return field_width + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
}

// A titled separator (ImGui 1.89's SeparatorText).
inline void section(const char* title) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", title);
  ImGui::Separator();
}

// A progress bar with its message and a Cancel button; true when Cancel was pressed. A message too
// long for the bar is written whole above it (ImGui clips a bar's text at both ends), the bar then
// showing the percentage.
inline bool progress_with_cancel(const char* id, float fraction, const char* message) {
  ImGui::PushID(id);
  const float bar = ImGui::GetContentRegionAvail().x - 90.0f;
  const bool fits = ImGui::CalcTextSize(message).x + 2.0f * ImGui::GetStyle().FramePadding.x <= bar;
  if (!fits) ImGui::TextWrapped("%s", message);
  ImGui::ProgressBar(fraction, {-90.0f, 0.0f}, fits ? message : nullptr);
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  ImGui::PopID();
  return cancel;
}

// `text` as wide as `width` at most: its end kept, its start replaced by "..." (a path's file name
// says more than its first folders).
inline std::string fitted_from_the_end(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  std::size_t from = 0;
  while (from < text.size() && ImGui::CalcTextSize(("..." + text.substr(from)).c_str()).x > width) ++from;
  while (from < text.size() && (static_cast<unsigned char>(text[from]) & 0xC0) == 0x80) ++from;  // whole UTF-8
  return "..." + text.substr(from);
}

// "40 s", "6.5 min", "42 min": a duration as a person reads it.
inline std::string duration_words(double seconds) {
  char text[32];
  if (seconds < 120.0) std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 600.0) std::snprintf(text, sizeof text, "%.1f min", seconds / 60.0);
  else std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
  return text;
}

}  // namespace nibrig::ui::panel
