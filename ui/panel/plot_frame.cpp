#include "ui/panel/plot_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace nibrig::ui::panel {

PlotFrame::PlotFrame(ImVec2 origin, ImVec2 size, DataRange x, DataRange y)
    : origin_(origin), size_(size), x_(x), y_(y) {}

ImVec2 PlotFrame::to_screen(double x, double y) const {
  const double u = (x - x_.min) / x_.span(), v = (y - y_.min) / y_.span();
  return {origin_.x + static_cast<float>(u * size_.x), origin_.y + static_cast<float>((1.0 - v) * size_.y)};
}

double PlotFrame::x_of(float screen_x) const { return x_.min + (screen_x - origin_.x) / size_.x * x_.span(); }

double PlotFrame::y_of(float screen_y) const {
  return y_.min + (1.0 - (screen_y - origin_.y) / size_.y) * y_.span();
}

bool PlotFrame::contains(ImVec2 p) const {
  return p.x >= origin_.x && p.y >= origin_.y && p.x <= origin_.x + size_.x && p.y <= origin_.y + size_.y;
}

DataRange padded(double lo, double hi, double margin) {
  if (!(hi > lo)) return {lo - 1.0, lo + 1.0};
  const double pad = (hi - lo) * margin;
  return {lo - pad, hi + pad};
}

std::vector<double> nice_ticks(DataRange range, int target) {
  const double raw = range.span() / std::max(1, target);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= raw) {
      step = m * decade;
      break;
    }
  std::vector<double> ticks;
  for (double t = std::ceil(range.min / step) * step; t <= range.max + 1e-9 * step; t += step)
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  return ticks;
}

void draw_grid(ImDrawList* draw, const PlotFrame& frame) {
  const ImU32 grid = IM_COL32(255, 255, 255, 28);
  const ImVec2 o = frame.origin(), s = frame.size();
  for (double t : nice_ticks(frame.x())) {
    const float x = frame.to_screen(t, frame.y().min).x;
    draw->AddLine({x, o.y}, {x, o.y + s.y}, grid);
  }
  for (double t : nice_ticks(frame.y())) {
    const float y = frame.to_screen(frame.x().min, t).y;
    draw->AddLine({o.x, y}, {o.x + s.x, y}, grid);
  }
}

void draw_axis_labels(ImDrawList* draw, const PlotFrame& frame, const std::string& x_name,
                      const std::string& y_name) {
  const ImU32 edge = IM_COL32(255, 255, 255, 110), text = IM_COL32(220, 220, 220, 255);
  const ImVec2 o = frame.origin(), s = frame.size();
  char label[32];
  for (double t : nice_ticks(frame.x())) {
    const float x = frame.to_screen(t, frame.y().min).x;
    std::snprintf(label, sizeof label, "%g", t);
    draw->AddText({x - 8.0f, o.y + s.y + 3.0f}, text, label);
  }
  for (double t : nice_ticks(frame.y())) {
    const float y = frame.to_screen(frame.x().min, t).y;
    std::snprintf(label, sizeof label, "%g", t);
    draw->AddText({o.x - 8.0f * static_cast<float>(std::strlen(label)) - 6.0f, y - 7.0f}, text, label);
  }
  draw->AddRect(o, {o.x + s.x, o.y + s.y}, edge);
  draw->AddText({o.x + s.x * 0.5f - 4.0f * static_cast<float>(x_name.size()), o.y + s.y + 20.0f}, text,
                x_name.c_str());
  draw->AddText({o.x + 4.0f, o.y - 18.0f}, text, y_name.c_str());
}

void draw_axes(ImDrawList* draw, const PlotFrame& frame, const std::string& x_name,
               const std::string& y_name) {
  draw_grid(draw, frame);
  draw_axis_labels(draw, frame, x_name, y_name);
}

void draw_marker(ImDrawList* draw, ImVec2 at, Marker marker, float r, ImU32 colour, bool filled) {
  switch (marker) {
    case Marker::circle:
      filled ? draw->AddCircleFilled(at, r, colour, 16) : draw->AddCircle(at, r, colour, 16, 1.5f);
      break;
    case Marker::square:
      filled ? draw->AddRectFilled({at.x - r, at.y - r}, {at.x + r, at.y + r}, colour)
             : draw->AddRect({at.x - r, at.y - r}, {at.x + r, at.y + r}, colour, 0.0f, 0, 1.5f);
      break;
    case Marker::triangle: {
      const ImVec2 a{at.x, at.y - r * 1.2f}, b{at.x - r * 1.1f, at.y + r * 0.8f}, c{at.x + r * 1.1f, at.y + r * 0.8f};
      filled ? draw->AddTriangleFilled(a, b, c, colour) : draw->AddTriangle(a, b, c, colour, 1.5f);
      break;
    }
    case Marker::diamond: {
      const ImVec2 a{at.x, at.y - r * 1.3f}, b{at.x + r * 1.3f, at.y}, c{at.x, at.y + r * 1.3f}, d{at.x - r * 1.3f, at.y};
      filled ? draw->AddQuadFilled(a, b, c, d, colour) : draw->AddQuad(a, b, c, d, colour, 1.5f);
      break;
    }
  }
}

void draw_ellipse(ImDrawList* draw, const PlotFrame& frame, double cx, double cy, double a, double b,
                  double angle_rad, ImU32 colour, float thickness, int segments) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  for (int k = 0; k < segments; ++k) {
    const double t = 2.0 * M_PI * k / segments;
    const double u = a * std::cos(t), v = b * std::sin(t);
    draw->PathLineTo(frame.to_screen(cx + c * u - s * v, cy + s * u + c * v));
  }
  draw->PathStroke(colour, ImDrawFlags_Closed, thickness);
}

void draw_trace(ImDrawList* draw, const PlotFrame& frame, const std::vector<double>& x,
                const std::vector<double>& y, ImU32 colour, float thickness) {
  const ImVec2 o = frame.origin(), s = frame.size();
  draw->PushClipRect(o, {o.x + s.x, o.y + s.y}, true);
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) draw->PathLineTo(frame.to_screen(x[i], y[i]));
  draw->PathStroke(colour, 0, thickness);
  draw->PopClipRect();
}

}  // namespace nibrig::ui::panel
