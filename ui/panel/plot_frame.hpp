// The few drawing pieces the views share, on ImGui's draw list (ImPlot is not packaged in Debian
// 12): a rectangle of the window mapped to data coordinates, its axes with round-number ticks,
// markers by kind, and ellipses as polylines (ImGui 1.86 has no AddEllipse).
#pragma once

#include <string>
#include <vector>

#include "imgui.h"

namespace nibrig::ui::panel {

struct DataRange {
  double min = 0.0, max = 1.0;
  double span() const { return max - min; }
};

// Data (x right, y up) to screen pixels (y down) inside `origin`..`origin + size`.
class PlotFrame {
 public:
  PlotFrame(ImVec2 origin, ImVec2 size, DataRange x, DataRange y);
  ImVec2 to_screen(double x, double y) const;
  double x_of(float screen_x) const;
  double y_of(float screen_y) const;
  bool contains(ImVec2 screen) const;
  ImVec2 origin() const { return origin_; }
  ImVec2 size() const { return size_; }
  DataRange x() const { return x_; }
  DataRange y() const { return y_; }

 private:
  ImVec2 origin_, size_;
  DataRange x_, y_;
};

// A range around [lo, hi] widened by `margin` of its span on each side (a single value gets ±1).
DataRange padded(double lo, double hi, double margin = 0.08);
// Round tick values (1, 2, 5 × 10^k) inside the range, about `target` of them.
std::vector<double> nice_ticks(DataRange range, int target = 6);

// The frame, grid lines at the ticks, tick labels and the axis names: draw_grid (inside the frame)
// then draw_axis_labels (its outline and what is outside it).
void draw_axes(ImDrawList* draw, const PlotFrame& frame, const std::string& x_name,
               const std::string& y_name);
void draw_grid(ImDrawList* draw, const PlotFrame& frame);
void draw_axis_labels(ImDrawList* draw, const PlotFrame& frame, const std::string& x_name,
                      const std::string& y_name);

enum class Marker { circle, square, triangle, diamond };
void draw_marker(ImDrawList* draw, ImVec2 at, Marker marker, float radius, ImU32 colour, bool filled);

// The ellipse of semi-axes a, b (data units) turned by `angle_rad` about (cx, cy), as a closed
// polyline of `segments` points.
void draw_ellipse(ImDrawList* draw, const PlotFrame& frame, double cx, double cy, double a, double b,
                  double angle_rad, ImU32 colour, float thickness, int segments = 32);

// A polyline of (x[i], y[i]) clipped to the frame.
void draw_trace(ImDrawList* draw, const PlotFrame& frame, const std::vector<double>& x,
                const std::vector<double>& y, ImU32 colour, float thickness = 1.5f);

}  // namespace nibrig::ui::panel
