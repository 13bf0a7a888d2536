// View 4, the pad: draw with the mouse or a tablet pen and the stroke's speed drives the engine
// live (Engine::set_contact through PanelAudio), with the speed trace under the canvas and the tool
// and surface in use. GLFW 3.3 reports no pen pressure (ImGui's io.PenPressure stays unfilled), so
// the force is a slider; the speed is the pointer's, in millimetres of the screen.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "imgui.h"
#include "ui/panel/panel_audio.hpp"

namespace nibrig::ui::panel {

class PadView {
 public:
  explicit PadView(PanelAudio& audio);
  void draw();
  // The speed the pad last sent (mm/s) and whether the pen is down; the trace.
  double speed_mm_s() const { return speed_mm_s_; }
  bool drawing() const { return drawing_; }
  const std::deque<float>& trace() const { return trace_; }
  // Millimetres per screen pixel: 25.4 / the screen's dots per inch (96 unless set).
  void set_mm_per_pixel(double mm) { mm_per_pixel_ = mm; }
  // The tool the pad plays; loads it (in the background) when it changes.
  void use_tool(const ToolChoice& tool);
  const ToolChoice& tool() const { return tool_; }

 private:
  void update_speed(bool down, ImVec2 position, double now_s);

  PanelAudio& audio_;
  ToolChoice tool_{"cryon", "office"};
  bool loaded_ = false;
  float force_n_ = 2.2f;
  double mm_per_pixel_ = 25.4 / 96.0;
  bool drawing_ = false;
  ImVec2 last_{};
  double speed_mm_s_ = 0.0;
  // The last two pointer events while the pen is down (newest first) and how many there are.
  ImVec2 event_[2]{};
  double event_s_[2]{};
  int events_ = 0;
  std::vector<std::vector<ImVec2>> strokes_;  // in canvas coordinates
  std::deque<float> trace_;                   // speed per frame, the last 600
  char tool_text_[64] = "cryon", surface_text_[64] = "office";
};

}  // namespace nibrig::ui::panel
