#include "rig/printed_parts_drawing.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace nibrig::rig {
namespace {

using model::mechanics::CsgBox;
using model::mechanics::CsgCylinder;

// An A4 page across, in millimetres; each view at most this wide or tall on it.
constexpr double kSheetWidthMm = 297.0;
constexpr double kSheetViewMm = 120.0;
constexpr double kSheetMarginMm = 15.0;
constexpr double kSheetLineMm = 5.0;  // one line of text

std::string sheet_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  std::string s = text;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string sheet_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else
      out += c;
  }
  return out;
}

struct SheetBounds {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  void add(const Eigen::Vector3d& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); }
};

SheetBounds solid_bounds(const model::mechanics::CsgSolid& solid) {
  SheetBounds b;
  for (const auto& box : solid.boxes) b.add(box.lo), b.add(box.hi);
  for (const auto& c : solid.cylinders)
    for (const auto& end : {c.base, Eigen::Vector3d(c.base + c.axis)})
      b.add(end - Eigen::Vector3d::Constant(c.radius)),
          b.add(end + Eigen::Vector3d::Constant(c.radius));
  return b;
}

// One orthographic view: the part's axes `u` (right) and `v` (up) in mm, placed with its lower
// left corner at (left, bottom) on the sheet, `k` sheet mm per part mm.
class SheetView {
 public:
  SheetView(int u, int v, double left, double bottom, double k, const SheetBounds& bounds)
      : u_(u), v_(v), left_(left), bottom_(bottom), k_(k), lo_(bounds.lo * 1e3) {}

  double x(const Eigen::Vector3d& p_m) const { return left_ + k_ * (1e3 * p_m[u_] - lo_[u_]); }
  double y(const Eigen::Vector3d& p_m) const { return bottom_ - k_ * (1e3 * p_m[v_] - lo_[v_]); }

  void box(std::ostringstream& out, const CsgBox& b, const char* style) const {
    const double x0 = x(b.lo), x1 = x(b.hi), y0 = y(b.hi), y1 = y(b.lo);
    out << "<rect x='" << x0 << "' y='" << y0 << "' width='" << x1 - x0 << "' height='" << y1 - y0
        << "' " << style << "/>\n";
  }

  // Seen end on, a cylinder is a circle; seen from the side, the rectangle it sweeps, dashed as
  // hidden.
  void cylinder(std::ostringstream& out, const CsgCylinder& c, bool cut) const {
    const Eigen::Vector3d dir = c.axis.normalized();
    const bool end_on = std::abs(dir[u_]) < 1e-9 && std::abs(dir[v_]) < 1e-9;
    if (end_on) {
      out << "<circle cx='" << x(c.base) << "' cy='" << y(c.base) << "' r='" << k_ * 1e3 * c.radius
          << "' "
          << (cut ? "fill='white' stroke='black' stroke-width='0.25'"
                  : "fill='#dde4ee' stroke='black' stroke-width='0.35'")
          << "/>\n";
      return;
    }
    Eigen::Vector3d lo = c.base.cwiseMin(c.base + c.axis), hi = c.base.cwiseMax(c.base + c.axis);
    for (int axis : {u_, v_})
      if (std::abs(dir[axis]) < 1e-9) lo[axis] -= c.radius, hi[axis] += c.radius;
    box(out, {lo, hi},
        cut ? "fill='none' stroke='black' stroke-width='0.2' stroke-dasharray='1,0.8'"
            : "fill='#dde4ee' stroke='black' stroke-width='0.35'");
  }

 private:
  int u_, v_;
  double left_, bottom_, k_;
  Eigen::Vector3d lo_;
};

void draw_view(std::ostringstream& out, const PrintedPart& part, const SheetView& view) {
  for (const auto& b : part.solid.boxes)
    view.box(out, b, "fill='#dde4ee' stroke='black' stroke-width='0.35'");
  for (const auto& c : part.solid.cylinders) view.cylinder(out, c, false);
  for (const auto& b : part.solid.box_cuts)
    view.box(out, b, "fill='white' stroke='black' stroke-width='0.25'");
  for (const auto& c : part.solid.cylinder_cuts) view.cylinder(out, c, true);
}

void text(std::ostringstream& out, double x, double y, const std::string& s, double size = 3.2,
          const char* anchor = "start") {
  out << "<text x='" << x << "' y='" << y << "' font-size='" << size << "' text-anchor='" << anchor
      << "'>" << sheet_escaped(s) << "</text>\n";
}

}  // namespace

std::string part_drawing_svg(const PrintedPart& part) {
  const SheetBounds bounds = solid_bounds(part.solid);
  const Eigen::Vector3d size_mm = (bounds.hi - bounds.lo) * 1e3;
  const double k = std::min(1.0, kSheetViewMm / size_mm.maxCoeff());
  const double top_left = kSheetMarginMm, front_left = kSheetMarginMm * 2 + k * size_mm.x() + 10;
  const double views_bottom = kSheetMarginMm + 12 + k * std::max(size_mm.y(), size_mm.z());
  std::ostringstream body;
  body.precision(4);
  text(body, kSheetMarginMm, kSheetMarginMm, "nibrig rig: " + part.title + " (" + part.name + ")",
       5);
  text(body, kSheetMarginMm, kSheetMarginMm + 6, part.purpose);
  // Top view (x right, y up) and front view (x right, z up), both as the part lies on the bed.
  draw_view(body, part, SheetView(0, 1, top_left, views_bottom, k, bounds));
  draw_view(body, part, SheetView(0, 2, front_left, views_bottom, k, bounds));
  const double label_y = views_bottom + 6;
  text(body, top_left, label_y,
       "top, on the bed: " + sheet_number(size_mm.x()) + " × " + sheet_number(size_mm.y()) + " mm");
  text(body, front_left, label_y,
       "front: " + sheet_number(size_mm.x()) + " × " + sheet_number(size_mm.z()) + " mm high");
  if (k < 1.0) text(body, top_left, label_y + kSheetLineMm, "scale 1:" + sheet_number(1.0 / k));

  double y = label_y + 2.5 * kSheetLineMm;
  text(body, kSheetMarginMm, y, "Dimensions (mm)", 4);
  for (const auto& dim : part.dimensions) {
    y += kSheetLineMm;
    text(body, kSheetMarginMm + 4, y, dim.label);
    text(body, kSheetMarginMm + 120, y, sheet_number(dim.value * 1e3), 3.2, "end");
  }
  y += 2 * kSheetLineMm;
  const auto& s = part.settings;
  text(body, kSheetMarginMm, y, "Print", 4);
  y += kSheetLineMm;
  text(body, kSheetMarginMm + 4, y,
       s.material + ", " + sheet_number(s.layer_height * 1e3) + " mm layers, " +
           std::to_string(s.perimeters) + " perimeters, " + std::to_string(s.top_layers) +
           " top / " + std::to_string(s.bottom_layers) + " bottom layers, " +
           std::to_string(s.fill_percent) + " % " + s.fill_pattern + ", no supports");
  y += kSheetLineMm;
  text(body, kSheetMarginMm + 4, y, "lies " + s.orientation, 2.6);
  y += 2 * kSheetLineMm;
  text(body, kSheetMarginMm, y, "Hardware", 4);
  for (const auto& h : part.hardware) {
    y += kSheetLineMm;
    text(body, kSheetMarginMm + 4, y, h);
  }
  const double height = y + kSheetMarginMm;
  std::ostringstream out;
  out << "<?xml version='1.0' encoding='UTF-8'?>\n"
      << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kSheetWidthMm << "mm' height='"
      << height << "mm' viewBox='0 0 " << kSheetWidthMm << " " << height
      << "' font-family='sans-serif'>\n"
      << "<rect width='100%' height='100%' fill='white'/>\n"
      << body.str() << "</svg>\n";
  return out.str();
}

}  // namespace nibrig::rig
