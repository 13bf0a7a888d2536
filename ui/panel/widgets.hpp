// Small widgets the views share that ImGui 1.86 lacks.
#pragma once

#include "imgui.h"

namespace nibrig::ui::panel {

// A titled separator (ImGui 1.89's SeparatorText).
inline void section(const char* title) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", title);
  ImGui::Separator();
}

// A progress bar with its message and a Cancel button; true when Cancel was pressed.
inline bool progress_with_cancel(const char* id, float fraction, const char* message) {
  ImGui::PushID(id);
  ImGui::ProgressBar(fraction, {-90.0f, 0.0f}, message);
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  ImGui::PopID();
  return cancel;
}

}  // namespace nibrig::ui::panel
