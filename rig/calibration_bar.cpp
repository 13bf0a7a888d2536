#include "rig/calibration_bar.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/design/printability.hpp"
#include "model/design/slicer_settings.hpp"

namespace nibrig::rig {
namespace {

namespace mech = model::mechanics;

// The FEM's frame has x = 0 at the clamp's edge and z centred in the thickness; the print's has
// x = 0 at the clamped end and z = 0 on the bed.
Eigen::Vector3d fem_to_print(const mech::BarGeometry& g, const Eigen::Vector3d& p) {
  return {p.x() + g.clamp_length, p.y(), p.z() + g.thickness / 2};
}

int setting_int(const model::io::PrinterProfile& printer, const std::string& key, int fallback) {
  const std::string text = printer.slicer_setting(key);
  try {
    return text.empty() ? fallback : std::stoi(text);
  } catch (const std::exception&) {
    return fallback;
  }
}

}  // namespace

CalibrationBar calibration_bar_of(const std::string& material, const mech::MaterialTable& materials,
                                  std::optional<double> length_m) {
  CalibrationBar bar;
  bar.material = materials.find(material).name;
  if (length_m) bar.geometry.length = *length_m;
  return bar;
}

mech::Design calibration_bar_design(const CalibrationBar& bar) {
  return mech::bar_design(bar.geometry, bar.material);
}

Eigen::Vector3d bar_sensor_on_print(const CalibrationBar& bar) {
  return fem_to_print(bar.geometry, mech::default_sensor(bar.geometry).point);
}

Eigen::Vector3d bar_tip_on_print(const CalibrationBar& bar) {
  return fem_to_print(bar.geometry, mech::default_tip(bar.geometry).point);
}

PrintedPart calibration_bar_part(const CalibrationBar& bar,
                                 const model::io::PrinterProfile& printer) {
  const mech::BarGeometry& g = bar.geometry;
  mech::validate(g);
  const double w = g.width, t = g.thickness, r = g.end_radius, end = g.length - r;
  PrintedPart part;
  part.name = "calibration_bar";
  part.title = "ring-down calibration bar";
  part.purpose = "Clamp the square end, pull the round end aside and let go: its ring-down fits " +
                 bar.material + "'s modulus and damping (nibrig material calibrate ringdown)";
  mech::CsgSolid& s = part.solid;
  s.boxes.push_back({{0, -w / 2, 0}, {end, w / 2, t}});
  if (r > 0) {
    // Rounded corners: a box between the two corner circles, or one semicircle when r = w/2.
    const double inner = w / 2 - r;
    if (inner > 1e-9) s.boxes.push_back({{end - 1e-9, -inner, 0}, {g.length, inner, t}});
    for (double y : inner > 1e-9 ? std::vector<double>{-inner, inner} : std::vector<double>{0.0})
      s.cylinders.push_back({{end, y, 0}, {0, 0, t}, r});
  }
  if (g.cutout)  // through the thickness, overshooting both faces so no skin is left
    s.cylinder_cuts.push_back(
        {{g.length - g.cutout_offset, 0, -t}, {0, 0, 3 * t}, g.cutout_radius});

  PrintSettings& p = part.settings;
  p.material = bar.material;
  p.layer_height = printer.layer_height_m;
  p.perimeters = setting_int(printer, "perimeters", 0);
  p.top_layers = setting_int(printer, "top_solid_layers", 0);
  p.bottom_layers = setting_int(printer, "bottom_solid_layers", 0);
  p.fill_percent = 100;
  p.fill_pattern = printer.slicer_setting("fill_pattern");
  p.orientation = "flat, the 2 mm thickness upright: layers along the bar, as a stylus lies";
  const Eigen::Vector3d sensor = bar_sensor_on_print(bar), tip = bar_tip_on_print(bar);
  part.dimensions = {{"length", g.length},
                     {"width", g.width},
                     {"thickness", g.thickness},
                     {"end radius", g.end_radius},
                     {"hole radius", g.cutout ? g.cutout_radius : 0.0},
                     {"hole centre from the round end", g.cutout ? g.cutout_offset : 0.0},
                     {"clamped from the square end", g.clamp_length},
                     {"accelerometer centre from the square end", sensor.x()},
                     {"preload: pull the round end aside by", bar.preload},
                     {"pulled at, from the square end", tip.x()}};
  part.hardware = {
      "a vice or two clamps holding the first " + fmt::format("{:g}", g.clamp_length * 1e3) +
          " mm rigidly on a heavy table, the bar flat",
      "the accelerometer glued (cyanoacrylate) on the top face's centre line at " +
          fmt::format("{:g}", sensor.x() * 1e3) + " mm, its measuring axis through the thickness",
      "a ruler standing at the free end to pull it " + fmt::format("{:g}", bar.preload * 1e3) +
          " mm aside before letting go"};
  return part;
}

std::vector<std::string> calibration_bar_refusals(const model::io::PrinterProfile& printer,
                                                  const CalibrationBar& bar) {
  std::vector<std::string> reasons;
  const mech::BarGeometry& g = bar.geometry;
  if (!model::design::printer_has(printer, bar.material)) {
    std::string list;
    for (const auto& m : printer.materials) list += (list.empty() ? "" : ", ") + m;
    reasons.push_back(bar.material + " is not a material it prints (it prints " + list + ")");
  }
  // Lying flat the bar may turn on the bed: its length along the bed's longer side.
  const double bed_long = std::max(printer.build_volume_m[0], printer.build_volume_m[1]);
  const double bed_short = std::min(printer.build_volume_m[0], printer.build_volume_m[1]);
  if (g.length > bed_long || g.width > bed_short || g.thickness > printer.build_volume_m[2])
    reasons.push_back(fmt::format(
        "the {:g} × {:g} mm bar does not fit its {:g} × {:g} mm bed: give a length of at most {:g} "
        "mm "
        "(with the clamp kept at {:g} mm)",
        g.length * 1e3, g.width * 1e3, printer.build_volume_m[0] * 1e3,
        printer.build_volume_m[1] * 1e3, std::floor(bed_long * 1e3), g.clamp_length * 1e3));
  const double smallest = model::design::smallest_tip_m(printer);
  const double rim =
      g.cutout ? std::min(g.width / 2 - g.cutout_radius, g.cutout_offset - g.cutout_radius)
               : g.width;
  if (std::min(g.thickness, rim) < smallest)
    reasons.push_back(fmt::format("its thinnest wall, {:g} mm, is below the {:g} mm it resolves",
                                  std::min(g.thickness, rim) * 1e3, smallest * 1e3));
  return reasons;
}

}  // namespace nibrig::rig
