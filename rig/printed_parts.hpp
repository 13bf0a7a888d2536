// The rig's printed parts (rig/HARDWARE.md, Mechanics; rig/PARTS.md): the arm's pivot post, the
// bearing bridge, the load cells' bracket, the tool holder and the accelerometer's mount, each a
// solid of boxes and holes derived from the rig's documented figures, with the print settings its
// load asks for. Geometry only; rig/printed_parts_files.hpp writes them.
#pragma once

#include <string>
#include <vector>

#include "model/mechanics/csg_solid.hpp"

namespace nibrig::rig {

// Every figure the parts are drawn from, in metres. The first group is the rig as HARDWARE.md
// documents it; then the bought parts' catalogue figures; then what FDM printing takes off.
struct RigPartDimensions {
  double track_radius = 0.060;        // the tip's distance from the disc's axis
  double tip_ahead_of_pivot = 0.150;  // along the arm, which lies on the track's tangent
  double disc_radius = 0.100;         // Ø200 × 5 mm disc
  double bearing_spacing = 0.040;     // the shaft's two KFL000 flange bearings
  double arm_width = 0.010;           // the 10 × 20 mm bar, 20 mm tall
  double arm_height = 0.020;
  double fixed_clearance = 0.010;  // Safety: 10 mm between the disc and anything fixed
  // Disc surface above the base's top: the upper bearing at 40 mm, its housing, the flange hub and
  // the 5 mm disc. The hub clamps anywhere on the shaft, so this is the nominal stack, not a fit.
  double disc_surface_height = 0.070;
  double tool_stick_out = 0.015;  // the tip below the accelerometer's collar, set by hand

  // 626-2RS: 6 × 19 × 6 mm (ISO 15 dimension series 626).
  double pin_diameter = 0.006;
  double pivot_bearing_od = 0.019;
  double pivot_bearing_width = 0.006;
  double pin_washer = 0.001;  // a washer on the pin between the arm and the bearing's inner ring
  double extrusion_side = 0.020;  // the post's 20 × 20 mm extrusion, M5 T-nuts in its slots
  double extrusion_screw = 0.005;
  double post_adjustment =
      0.005;  // the post slides this much either way on its extrusion to level the arm
  // KFL000 (two-bolt rhombic flange, zinc alloy, 10 mm bore) as vendors list it: 60 mm over the
  // flange, bolt holes 45 mm apart for M6. Not checked against a datasheet here: measure yours
  // (rig/PARTS.md).
  double flange_bearing_length = 0.060;
  double flange_bearing_bolt_spacing = 0.045;
  double flange_bearing_bolt = 0.006;
  double flange_bearing_boss = 0.028;  // clearance for the housing's back and the insert's collar
  double base_screw = 0.005;           // the bridge's legs to the base
  // TAL220-type straight bar: 80 × 12.7 × 12.7 mm, at each end two threaded holes 15 mm apart, the
  // outer 5 mm from the end (M5 on the 1 kg cells sold with this drawing; some ends are M4).
  double cell_length = 0.080;
  double cell_section = 0.0127;
  double cell_hole_from_end = 0.005;
  double cell_hole_spacing = 0.015;
  double cell_screw = 0.005;
  double cell_end_block =
      0.024;  // the solid end a mount may touch; the flexure's twin hole starts after it
  double cell_spacer =
      0.002;  // under the normal cell's fixed end, so its free end flexes clear of the arm
  double cell_gap = 0.002;  // between a cell's end and the part in front of it
  // Tools Ø6–12 mm; set screws M3, nylon-tipped, in M3 heat-set inserts (5.7 mm long, Ø4.0 hole as
  // their makers recommend).
  double tool_max_diameter = 0.012;
  double set_screw = 0.003;
  double insert_hole = 0.0040;
  double insert_length = 0.0057;
  // EVAL-ADXL1002Z: the pad takes any board up to this size, glued as HARDWARE.md says; its lower
  // lip squares the board's edge to the track.
  double board_width = 0.022;
  double board_height = 0.020;

  // FDM: a vertical hole comes out 0.1–0.3 mm under its drawn diameter (the first perimeter is
  // squashed inward, and the slicer's polygon lies inside the circle); every clearance hole is
  // drawn 0.2 mm over its nominal size.
  double hole_shrink = 0.0002;
  // A bearing seat is drawn 0.1 mm over the ring, so that the 0.2 mm a hole loses leaves about
  // 0.1 mm of press: the ring goes in with a vice and does not turn.
  double press_fit_allowance = 0.0001;
  // The tool's bore is drawn 0.6 mm over the largest tool: 0.4 mm of slip once printed, so a
  // Ø12 mm tool slides in by hand and the set screws take up the play.
  double tool_clearance = 0.0006;
  double wall = 0.004;  // the thinnest wall around a hole: 4 perimeters of 0.45 mm with margin
};

// ISO 273's medium clearance for a metric screw (M3–M6), plus the hole's print shrinkage. Throws
// std::invalid_argument naming the size for any other screw.
double clearance_hole(double screw_diameter, const RigPartDimensions& d);

// What PrusaSlicer is told for one part (rig/printed_parts_files.hpp writes it as an .ini).
struct PrintSettings {
  std::string material = "PETG";
  double layer_height = 0.0002;  // m
  int perimeters = 4;
  int top_layers = 5;
  int bottom_layers = 4;
  int fill_percent = 50;
  std::string fill_pattern = "gyroid";
  int nozzle_temperature_C = 240;
  int bed_temperature_C = 85;
  std::string orientation;  // how the part lies on the bed, and why: the load against the layers
};

struct PartDimension {
  std::string label;
  double value = 0.0;  // m
};

struct PrintedPart {
  std::string name;   // the files' stem: "arm_post"
  std::string title;  // "arm post"
  std::string purpose;
  // In the orientation it prints: z up from the bed, the lowest point at z = 0.
  model::mechanics::CsgSolid solid;
  PrintSettings settings;
  std::vector<PartDimension> dimensions;  // the figures a drawing shows and a fitter checks
  std::vector<std::string> hardware;      // what is fitted to it
};

// The five parts, in assembly order: arm_post, bearing_bridge, cell_bracket, tool_holder,
// accelerometer_mount. Throws std::invalid_argument naming the figure when the dimensions make a
// part impossible (a wall thinner than `wall`, the post within `fixed_clearance` of the rim).
std::vector<PrintedPart> rig_printed_parts(const RigPartDimensions& d = {});

// The pivot's height above the base's top that makes the arm level with the tip on the disc: the
// disc's surface plus the chain from the pivot down to the tip (arm, normal cell, bracket,
// tangential cell, holder, collar, the tool's stick-out).
double pivot_height(const RigPartDimensions& d);
// The 20 × 20 extrusion's length for the post: its top meets the top of the post's screw zone.
double post_extrusion_length(const RigPartDimensions& d);
// The nearest the post comes to the disc's rim, seen from above.
double post_rim_clearance(const RigPartDimensions& d);

}  // namespace nibrig::rig
