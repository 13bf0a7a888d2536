#include "ui/panel/pad_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/panel/plot_frame.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace {

// A pen held still for this long after its last event has stopped (a mouse reports at 60-1000 Hz,
// so a gap of 50 ms is no longer a gap between events).
constexpr double kStoppedAfter_s = 0.05;
constexpr std::size_t kTraceLength = 600;

}  // namespace

PadView::PadView(PanelAudio& audio) : audio_(audio) {}

void PadView::use_tool(const ToolChoice& tool) {
  tool_ = tool;
  std::snprintf(tool_text_, sizeof tool_text_, "%s", tool.tool.c_str());
  std::snprintf(surface_text_, sizeof surface_text_, "%s", tool.surface.c_str());
  audio_.play({tool_}, true);  // no motion until the pen moves
  loaded_ = true;
}

void PadView::update_speed(bool down, ImVec2 p, double now_s) {
  if (!down) {
    speed_mm_s_ = 0.0;
    events_ = 0;
  } else if (!drawing_ || p.x != last_.x || p.y != last_.y) {
    // A new pointer event: the speed over the last two events' intervals. Frames between events
    // (the display outruns the mouse) hold it, where a per-frame difference read each frame without
    // a move as a stop and spiked on the next; two intervals average the event timing's jitter
    // with at most one event of lag.
    if (events_ >= 2) {
      const double dt = std::max(1e-3, now_s - event_s_[1]);
      const double dx = p.x - event_[1].x, dy = p.y - event_[1].y;
      speed_mm_s_ = std::sqrt(dx * dx + dy * dy) * mm_per_pixel_ / dt;
    } else if (events_ == 1) {
      const double dt = std::max(1e-3, now_s - event_s_[0]);
      const double dx = p.x - event_[0].x, dy = p.y - event_[0].y;
      speed_mm_s_ = std::sqrt(dx * dx + dy * dy) * mm_per_pixel_ / dt;
    }
    event_[1] = event_[0], event_s_[1] = event_s_[0];
    event_[0] = p, event_s_[0] = now_s;
    events_ = std::min(events_ + 1, 2);
  } else if (now_s - event_s_[0] > kStoppedAfter_s) {
    speed_mm_s_ = 0.0;  // held still on the pad: a stop, and the next move is timed from now
    event_s_[0] = now_s;
    events_ = 1;
  }
  drawing_ = down;
  last_ = p;
}

void PadView::draw() {
  section("Tool");
  ImGui::SetNextItemWidth(140.0f);
  ImGui::InputText("tool", tool_text_, sizeof tool_text_);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(140.0f);
  ImGui::InputText("surface", surface_text_, sizeof surface_text_);
  ImGui::SameLine();
  if (ImGui::Button(loaded_ ? "Use" : "Load")) use_tool({tool_text_, surface_text_});
  ImGui::SameLine();
  ImGui::SetNextItemWidth(160.0f);
  ImGui::SliderFloat("force N", &force_n_, 0.5f, 4.0f, "%.1f");
  if (!loaded_) ImGui::Text("press Load to draw with %s on %s", tool_text_, surface_text_);
  else ImGui::Text("in use: %s on %s%s", tool_.tool.c_str(), tool_.surface.c_str(),
                   audio_.making_sounds() ? " (being made)" : "");

  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 canvas_size{avail.x, std::max(100.0f, avail.y - 150.0f)};
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, {origin.x + canvas_size.x, origin.y + canvas_size.y}, IM_COL32(245, 242, 232, 255));
  ImGui::InvisibleButton("pad-canvas", canvas_size);
  const ImGuiIO& io = ImGui::GetIO();
  const bool down = ImGui::IsItemActive() && io.MouseDown[0];
  const ImVec2 p{io.MousePos.x - origin.x, io.MousePos.y - origin.y};
  if (down && !drawing_) strokes_.emplace_back();
  if (down) strokes_.back().push_back(p);
  const bool was = drawing_;
  update_speed(down, p, ImGui::GetTime());
  if (down || was) audio_.contact(speed_mm_s_ * 1e-3, down ? force_n_ : 0.0);
  if (strokes_.size() > 64) strokes_.erase(strokes_.begin());
  draw->PushClipRect(origin, {origin.x + canvas_size.x, origin.y + canvas_size.y}, true);
  for (const auto& stroke : strokes_) {
    for (const auto& q : stroke) draw->PathLineTo({origin.x + q.x, origin.y + q.y});
    draw->PathStroke(IM_COL32(40, 40, 48, 255), 0, 2.0f);
  }
  draw->PopClipRect();

  trace_.push_back(static_cast<float>(speed_mm_s_));
  while (trace_.size() > kTraceLength) trace_.pop_front();
  const ImVec2 at{origin.x + 50.0f, origin.y + canvas_size.y + 26.0f};
  const PlotFrame frame(at, {canvas_size.x - 70.0f, 90.0f}, {-static_cast<double>(kTraceLength), 0.0}, {0.0, 300.0});
  std::vector<double> x(trace_.size()), y(trace_.begin(), trace_.end());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i) - static_cast<double>(x.size());
  draw_axes(draw, frame, "frames", "speed mm/s");
  draw_trace(draw, frame, x, y, IM_COL32(86, 180, 233, 255));
  ImGui::SetCursorScreenPos({origin.x, at.y + 112.0f});
  ImGui::Text("%.0f mm/s%s", speed_mm_s_, speed_mm_s_ > 250.0 ? " (beyond the measured 250 mm/s: the fastest spectrum is held)" : "");
}

}  // namespace nibrig::ui::panel
