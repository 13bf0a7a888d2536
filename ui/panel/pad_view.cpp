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

void PadView::follow_mouse(ImVec2 origin) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool down = ImGui::IsItemActive() && io.MouseDown[0];
  const ImVec2 p{io.MousePos.x - origin.x, io.MousePos.y - origin.y};
  if (down && !drawing_) strokes_.emplace_back();
  if (down) strokes_.back().push_back(p);
  const bool was = drawing_;
  update_speed(down, p, ImGui::GetTime());
  sent_force_n_ = down ? force_n_ : 0.0;
  if (down || was) audio_.contact(speed_mm_s_ * 1e-3, sent_force_n_);
}

// The pen's newest contact to the engine, and its strokes onto the canvas: the tablet's area
// scaled to fit the canvas, its aspect kept.
void PadView::follow_pen(rig::pen::PenStylus& stylus, ImVec2 size) {
  stylus.tick();
  if (const auto contact = stylus.take()) {
    audio_.contact(contact->speed_m_s, contact->force_n);
    speed_mm_s_ = 1e3 * contact->speed_m_s;
    sent_force_n_ = contact->force_n;
  }
  drawing_ = stylus.status().in_stroke;
  const auto& t = stylus.tablet();
  const double w = t.width_mm > 0 ? t.width_mm : 150.0, h = t.height_mm > 0 ? t.height_mm : 100.0;
  const double scale = std::min(size.x / w, size.y / h);  // pixels per mm of the tablet
  for (const auto& point : stylus.take_path()) {
    if (point.stroke != pen_stroke_ || strokes_.empty()) {
      strokes_.emplace_back();
      pen_stroke_ = point.stroke;
    }
    strokes_.back().push_back({static_cast<float>(1e3 * point.x_m * scale), static_cast<float>(1e3 * point.y_m * scale)});
  }
}

std::string PadView::replay(const std::filesystem::path& file) {
  try {
    Replay r;
    r.drawing = model::io::read_paper_drawing(file);
    const auto& d = r.drawing;
    const auto [x_min, x_max] = std::minmax_element(d.x_m.begin(), d.x_m.end());
    const auto [y_min, y_max] = std::minmax_element(d.y_m.begin(), d.y_m.end());
    r.x_min_m = *x_min, r.x_max_m = *x_max, r.y_min_m = *y_min, r.y_max_m = *y_max;
    replay_ = std::move(r);
    replay_error_.clear();
    strokes_.clear();
  } catch (const std::exception& e) {
    replay_error_ = e.what();
  }
  return replay_error_;
}

// The recording's rows up to the pad's clock, as if a pen had sent them: the newest row's speed and
// force to the engine, the rows touching onto the canvas (the recording's millimetres, the
// canvas's scale fitted to its extent).
void PadView::follow_replay(ImVec2 size) {
  Replay& r = *replay_;
  const auto& d = r.drawing;
  const double now = ImGui::GetTime();
  if (r.started_s < 0) r.started_s = now;
  const double t = d.time_s.front() + (now - r.started_s);
  const double x_min = r.x_min_m, y_min = r.y_min_m;
  const double scale =
      0.9 * std::min(size.x / std::max(1e-3, r.x_max_m - x_min), size.y / std::max(1e-3, r.y_max_m - y_min));
  bool touching = drawing_;
  while (r.next < d.time_s.size() && d.time_s[r.next] <= t) {
    const std::size_t i = r.next++;
    if (d.touching[i] && !touching) strokes_.emplace_back();
    touching = d.touching[i];
    if (touching) {
      strokes_.back().push_back({static_cast<float>(0.05 * size.x + (d.x_m[i] - x_min) * scale),
                                 static_cast<float>(0.05 * size.y + (d.y_m[i] - y_min) * scale)});
    }
    speed_mm_s_ = touching ? 1e3 * d.speed_m_s[i] : 0.0;
    sent_force_n_ = touching ? d.normal_force_N[i] : 0.0;
  }
  drawing_ = touching;
  audio_.contact(speed_mm_s_ * 1e-3, sent_force_n_);
  if (r.next >= d.time_s.size()) {
    speed_mm_s_ = sent_force_n_ = 0.0;
    drawing_ = false;
    audio_.contact(0.0, 0.0);
    replay_.reset();
  }
}

void PadView::draw_traces(ImDrawList* draw, ImVec2 at, float width) {
  trace_.push_back(static_cast<float>(speed_mm_s_));
  force_trace_.push_back(static_cast<float>(sent_force_n_));
  while (trace_.size() > kTraceLength) trace_.pop_front();
  while (force_trace_.size() > kTraceLength) force_trace_.pop_front();
  const float half = (width - 60.0f) / 2.0f;
  const PlotFrame speed(at, {half - 50.0f, 90.0f}, {-static_cast<double>(kTraceLength), 0.0}, {0.0, 300.0});
  const PlotFrame force({at.x + half + 20.0f, at.y}, {half - 50.0f, 90.0f}, {-static_cast<double>(kTraceLength), 0.0},
                        {0.0, 5.0});
  std::vector<double> x(trace_.size()), y(trace_.begin(), trace_.end()), f(force_trace_.begin(), force_trace_.end());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i) - static_cast<double>(x.size());
  draw_axes(draw, speed, "frames", "speed mm/s");
  draw_trace(draw, speed, x, y, IM_COL32(86, 180, 233, 255));
  draw_axes(draw, force, "frames", "force N");
  draw_trace(draw, force, x, f, IM_COL32(230, 159, 0, 255));
}

void PadView::draw() {
  pen_.poll(ImGui::GetTime());
  rig::pen::PenStylus* stylus = pen_.stylus();
  section("Tool");
  // One row where the window is wide enough, wrapped where it is not (800 px cut the last button).
  ImGui::SetNextItemWidth(140.0f);
  ImGui::InputText("tool", tool_text_, sizeof tool_text_);
  same_line_if_fits(labelled_width("surface", 140.0f));
  ImGui::SetNextItemWidth(140.0f);
  ImGui::InputText("surface", surface_text_, sizeof surface_text_);
  const char* load = loaded_ ? "Use" : "Load";
  same_line_if_fits(button_width(load));
  if (ImGui::Button(load)) use_tool({tool_text_, surface_text_});
  if (!stylus) {
    same_line_if_fits(labelled_width("mouse force N", 160.0f));
    ImGui::SetNextItemWidth(160.0f);
    ImGui::SliderFloat("mouse force N", &force_n_, 0.5f, 4.0f, "%.1f");
  }
  const char* replay_label = replay_ ? "Stop the replay" : "Replay a stroke...";
  same_line_if_fits(button_width(replay_label));
  const bool replay_pressed = ImGui::Button(replay_label);
  replay_button_ = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
  if (replay_pressed) {
    if (replay_) {
      replay_.reset();
      drawing_ = false;
      speed_mm_s_ = sent_force_n_ = 0.0;
      audio_.contact(0.0, 0.0);
    } else {
      files_.open("Replay a recorded stroke", FileDialog::Mode::open, {".csv", ".csv.gz"}, {},
                  [this](const std::filesystem::path& file) { replay(file); });
    }
  }
  files_.draw();
  if (!replay_error_.empty()) ImGui::TextWrapped("%s", replay_error_.c_str());
  if (!loaded_) ImGui::Text("press Load to draw with %s on %s", tool_text_, surface_text_);
  else ImGui::Text("in use: %s on %s%s", tool_.tool.c_str(), tool_.surface.c_str(),
                   audio_.making_sounds() ? " (being made)" : "");
  ImGui::TextUnformatted(pen_.status().c_str());

  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 canvas_size{avail.x, std::max(100.0f, avail.y - 150.0f)};
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, {origin.x + canvas_size.x, origin.y + canvas_size.y}, IM_COL32(245, 242, 232, 255));
  ImGui::InvisibleButton("pad-canvas", canvas_size);
  if (replay_) follow_replay(canvas_size);
  else if (stylus) follow_pen(*stylus, canvas_size);
  else follow_mouse(origin);
  if (strokes_.size() > 64) strokes_.erase(strokes_.begin());
  draw->PushClipRect(origin, {origin.x + canvas_size.x, origin.y + canvas_size.y}, true);
  for (const auto& stroke : strokes_) {
    for (const auto& q : stroke) draw->PathLineTo({origin.x + q.x, origin.y + q.y});
    draw->PathStroke(IM_COL32(40, 40, 48, 255), 0, 2.0f);
  }
  draw->PopClipRect();

  const ImVec2 at{origin.x + 50.0f, origin.y + canvas_size.y + 26.0f};
  draw_traces(draw, at, canvas_size.x);
  ImGui::SetCursorScreenPos({origin.x, at.y + 112.0f});
  ImGui::Text("%.0f mm/s, %.2f N%s", speed_mm_s_, sent_force_n_,
              speed_mm_s_ > 250.0 ? " (beyond the measured 250 mm/s: the fastest spectrum is held)" : "");
}

}  // namespace nibrig::ui::panel
