#include "ui/panel/stroke_choice.hpp"

#include <cstdio>

#include "imgui.h"

namespace nibrig::ui::panel {

rt::StrokeRequest StrokeChoice::request() const {
  rt::StrokeRequest r;
  if (kind == 0) r.speed_m_s = speed_mm_s * 1e-3;
  if (kind == 2) r.trajectory = trajectory;
  r.force_n = force_n;
  return r;
}

bool stroke_widgets(StrokeChoice& c) {
  bool changed = false;
  const char* kinds[] = {"constant speed", "the rig's sweep", "an artist's trajectory"};
  changed |= ImGui::Combo("stroke", &c.kind, kinds, 3);
  if (c.kind == 0) changed |= ImGui::SliderFloat("speed mm/s", &c.speed_mm_s, 17.0f, 250.0f, "%.0f");
  if (c.kind == 2) {
    char path[512];
    std::snprintf(path, sizeof path, "%s", c.trajectory.c_str());
    if (ImGui::InputText("trajectory", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue)) {
      c.trajectory = path;
      changed = true;
    }
  }
  changed |= ImGui::SliderFloat("force N", &c.force_n, 0.5f, 4.0f, "%.1f");
  return changed;
}

}  // namespace nibrig::ui::panel
