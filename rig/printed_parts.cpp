#include "rig/printed_parts.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace nibrig::rig {
namespace {

using model::mechanics::CsgBox;
using model::mechanics::CsgCylinder;
using V = Eigen::Vector3d;

// A cut that passes through a wall is drawn this much longer at each end, so that its end faces
// never coincide with the wall's (coincident faces leave OpenCASCADE a sliver to guess at).
constexpr double kPartsCutOverrun = 0.0005;  // m
// The bridge's legs stand this far beyond each end of the lower bearing's flange: room for the
// lower bearing to go in and out with its bolts in place, and for a spanner on its nuts.
constexpr double kBridgeEndRoom = 0.006;
// The pad under the normal cell's free end stands this proud of the rest of the bracket, so that
// only the cell's solid end block ever touches it.
constexpr double kBracketPadRelief = 0.001;
// An insert's pocket is deeper than the insert: the plastic it melts aside flows ahead of it.
constexpr double kInsertPocketExtra = 0.0008;
// The web between an insert's pocket and the tool's bore, which the set screw passes through.
constexpr double kSetScrewWeb = 0.0015;
// The lip the accelerometer board stands on: as deep as the board is thick (1.6 mm) and a little.
constexpr double kBoardLipDepth = 0.002;
constexpr double kBoardLipHeight = 0.002;

CsgBox box(V lo, V hi) { return {lo, hi}; }

// A hole along `axis` (0 = x, 1 = y, 2 = z) through [from, to] on that axis, centred at `at`
// on the other two, overrunning both ends.
CsgCylinder hole(int axis, V at, double from, double to, double diameter) {
  V base = at, dir = V::Zero();
  base[axis] = from - kPartsCutOverrun;
  dir[axis] = to - from + 2 * kPartsCutOverrun;
  return {base, dir, diameter / 2};
}

// A blind hole from the face at `face` going `depth` into the part (negative depth: towards −axis).
CsgCylinder pocket(int axis, V at, double face, double depth, double diameter) {
  V base = at, dir = V::Zero();
  const double outward = depth > 0 ? -1.0 : 1.0;
  base[axis] = face + outward * kPartsCutOverrun;
  dir[axis] = depth - outward * kPartsCutOverrun;
  return {base, dir, diameter / 2};
}

void require_part(bool ok, const std::string& part, const std::string& why) {
  if (!ok) throw std::invalid_argument("rig part " + part + ": " + why);
}

std::string mm(double metres) {
  std::ostringstream out;
  out.precision(3);
  out << metres * 1e3 << " mm";
  return out.str();
}

double seat_diameter(const RigPartDimensions& d) {
  return d.pivot_bearing_od + d.press_fit_allowance;
}
double bore_diameter(const RigPartDimensions& d) { return d.tool_max_diameter + d.tool_clearance; }
double insert_pocket_depth(const RigPartDimensions& d) {
  return d.insert_length + kInsertPocketExtra;
}
double flange(const RigPartDimensions& d) {
  return 1.5 * d.wall;
}  // the bracket's and holder's plates

// ---- the arm's post: a plate on the extrusion's face, the pivot's bearings in its top ----
// Printed flat (the plate's face on the bed): both bearing seats and both screw holes are then
// vertical, round and true, and the layers lie in the plate's plane, the plane the arm's weight
// and the friction load it in.
struct PostLayout {
  double width, screw_zone, bore_y, height, thickness, through;
};

PostLayout post_layout(const RigPartDimensions& d) {
  PostLayout p{};
  p.width = 2 * d.extrusion_side;
  p.screw_zone = 2 * d.extrusion_side;  // two T-nut screws, one extrusion width apart
  // Above the extrusion's top by the pin's collar (Ø twice the pin) and the height it may slide.
  p.bore_y = p.screw_zone + d.pin_diameter + d.post_adjustment;
  p.height = p.bore_y + seat_diameter(d) / 2 + 1.5 * d.wall;
  // Two bearings, a shoulder as wide as one between them: the pin is held over three widths.
  p.thickness = 3 * d.pivot_bearing_width;
  // The shoulder bears on the outer ring only: its hole is wider than the turning inner ring.
  p.through = (d.pin_diameter + d.pivot_bearing_od) / 2;
  return p;
}

PrintedPart arm_post(const RigPartDimensions& d) {
  const PostLayout p = post_layout(d);
  const double screw = clearance_hole(d.extrusion_screw, d);
  require_part(p.bore_y - seat_diameter(d) / 2 - (1.5 * d.extrusion_side + screw / 2) >= d.wall,
               "arm_post", "the bearing seat runs into the upper extrusion screw");
  PrintedPart part;
  part.name = "arm_post";
  part.title = "arm post";
  part.purpose =
      "holds the arm's Ø6 mm pivot pin in two 626-2RS bearings, on the side of a vertical 20 × 20 "
      "extrusion";
  part.solid.boxes = {box({0, 0, 0}, {p.width, p.height, p.thickness})};
  const V bore(p.width / 2, p.bore_y, 0);
  part.solid.cylinder_cuts = {
      pocket(2, bore, 0, d.pivot_bearing_width, seat_diameter(d)),
      pocket(2, bore, p.thickness, -d.pivot_bearing_width, seat_diameter(d)),
      hole(2, bore, 0, p.thickness, p.through),
      hole(2, V(p.width / 2, d.extrusion_side / 2, 0), 0, p.thickness, screw),
      hole(2, V(p.width / 2, 1.5 * d.extrusion_side, 0), 0, p.thickness, screw),
  };
  part.settings.fill_percent = 50;
  part.settings.fill_pattern = "gyroid";
  part.settings.orientation =
      "flat, the face with the screw heads up: bearing seats and screw holes print vertical and "
      "round, and the "
      "layers lie in the plane the arm's load acts in";
  part.dimensions = {{"pivot above the base", pivot_height(d)},
                     {"extrusion length", post_extrusion_length(d)},
                     {"bearing seat (626, press)", seat_diameter(d)},
                     {"seat depth", d.pivot_bearing_width},
                     {"shoulder hole", p.through},
                     {"pin axis above the screw zone's foot", p.bore_y},
                     {"T-nut screw holes (M5)", screw},
                     {"screw spacing", d.extrusion_side},
                     {"plate", p.width},
                     {"height", p.height},
                     {"thickness", p.thickness}};
  part.hardware = {
      "2 × 626-2RS bearing, pressed in from each face",
      "Ø6 mm pin, with a 1 mm washer between the arm and each inner ring and a shaft collar behind",
      "2 × M5 × 25 screw with M5 T-nuts in the extrusion's slot",
      "20 × 20 extrusion, " + mm(post_extrusion_length(d)) + " long, on the base"};
  return part;
}

// ---- the bearing bridge: a deck 40 mm above the base on two legs, over the lower bearing ----
// Printed upside down, the deck on the bed: every hole is vertical and nothing overhangs. The
// legs then have their layers across them, where the bolts squeeze them: compression across
// layers is what a printed part takes best.
struct BridgeLayout {
  double inner, leg, length, depth, deck;
};

BridgeLayout bridge_layout(const RigPartDimensions& d) {
  BridgeLayout b{};
  b.inner = d.flange_bearing_length + 2 * kBridgeEndRoom;
  b.leg = clearance_hole(d.base_screw, d) + 2 * d.wall + 0.002;
  b.length = b.inner + 2 * b.leg;
  b.depth = d.flange_bearing_boss + 4 * d.wall;
  b.deck = 2 * d.wall;
  return b;
}

PrintedPart bearing_bridge(const RigPartDimensions& d) {
  const BridgeLayout b = bridge_layout(d);
  const double h = d.bearing_spacing;
  const double bolt = clearance_hole(d.flange_bearing_bolt, d),
               base = clearance_hole(d.base_screw, d);
  require_part(
      d.flange_bearing_bolt_spacing / 2 - bolt / 2 - d.flange_bearing_boss / 2 >= d.wall * 0.75,
      "bearing_bridge", "the bearing's bolt holes run into the shaft's clearance hole");
  require_part(h - b.deck > 0.02, "bearing_bridge",
               "the lower bearing needs more than 20 mm under the deck");
  PrintedPart part;
  part.name = "bearing_bridge";
  part.title = "bearing bridge";
  part.purpose =
      "holds the upper KFL000 flange bearing 40 mm above the lower one, over the disc's shaft";
  // Print coordinates: the deck's top (in use) on the bed at z = 0, the legs' feet at z = h.
  part.solid.boxes = {box({0, 0, 0}, {b.length, b.depth, b.deck}),
                      box({0, 0, b.deck}, {b.leg, b.depth, h}),
                      box({b.length - b.leg, 0, b.deck}, {b.length, b.depth, h})};
  const double cx = b.length / 2, cy = b.depth / 2;
  part.solid.cylinder_cuts = {
      hole(2, V(cx, cy, 0), 0, b.deck, d.flange_bearing_boss),
      hole(2, V(cx - d.flange_bearing_bolt_spacing / 2, cy, 0), 0, b.deck, bolt),
      hole(2, V(cx + d.flange_bearing_bolt_spacing / 2, cy, 0), 0, b.deck, bolt)};
  const double foot_y = d.wall + base / 2;
  for (double x : {b.leg / 2, b.length - b.leg / 2})
    for (double y : {foot_y, b.depth - foot_y})
      part.solid.cylinder_cuts.push_back(hole(2, V(x, y, 0), 0, h, base));
  part.settings.fill_percent = 50;
  part.settings.fill_pattern = "gyroid";
  part.settings.orientation =
      "upside down, the deck on the bed: all holes vertical, no overhang; the legs' layers are "
      "squeezed by the "
      "bolts, never pulled apart";
  part.dimensions = {{"deck top above the base (bearing spacing)", h},
                     {"between the legs", b.inner},
                     {"shaft and housing clearance", d.flange_bearing_boss},
                     {"KFL000 bolt spacing", d.flange_bearing_bolt_spacing},
                     {"KFL000 bolt holes (M6)", bolt},
                     {"base screw holes (M5)", base},
                     {"deck", b.deck},
                     {"length", b.length},
                     {"depth", b.depth}};
  part.hardware = {
      "upper KFL000 on the deck, 2 × M6 × 20 screws and nuts",
      "4 × M5 × 50 screws through the legs into the base (T-nuts in plywood, tapped in aluminium)"};
  return part;
}

// ---- the cell bracket: an L from the normal cell's free end to the tangential cell's fixed end
// ---- In use x runs forward along the arm and u up; printed on its side (the L's profile on the
// bed, print y = u + the vertical flange's length, print z across): both flanges and the corner
// between them are then laid in one layer, so the corner's bending pulls along the filaments.
struct BracketLayout {
  double t, width, horizontal, vertical;
};

BracketLayout bracket_layout(const RigPartDimensions& d) {
  BracketLayout b{};
  const double screw = clearance_hole(d.cell_screw, d);
  b.t = flange(d);
  b.width = d.cell_section + 0.004;  // 2 mm beyond the cell each side
  b.horizontal = d.cell_hole_from_end + d.cell_hole_spacing + screw / 2 + d.wall;
  b.vertical = b.t + d.cell_gap + d.cell_hole_from_end + d.cell_hole_spacing + screw / 2 + d.wall;
  return b;
}

PrintedPart cell_bracket(const RigPartDimensions& d) {
  const BracketLayout b = bracket_layout(d);
  const double screw = clearance_hole(d.cell_screw, d);
  require_part(b.horizontal - d.cell_end_block >= 0, "cell_bracket",
               "the cell's end block is longer than the flange");
  PrintedPart part;
  part.name = "cell_bracket";
  part.title = "cell bracket";
  part.purpose =
      "joins the normal cell's free end (level) to the tangential cell's fixed end (upright) at a "
      "right angle";
  const double y0 = b.vertical;  // print y of the pad's top (u = 0)
  const double Lh = b.horizontal, t = b.t, w = b.width;
  part.solid.boxes = {
      box({0, y0 - t, 0}, {Lh + t, y0 - kBracketPadRelief, w}),  // horizontal flange
      box({Lh - d.cell_end_block, y0 - kBracketPadRelief, 0},
          {Lh + t, y0, w}),                  // pad under the cell's end
      box({Lh, 0, 0}, {Lh + t, y0 - t, w}),  // vertical flange
  };
  for (double from_end : {d.cell_hole_from_end, d.cell_hole_from_end + d.cell_hole_spacing}) {
    part.solid.cylinder_cuts.push_back(hole(1, V(Lh - from_end, 0, w / 2), y0 - t, y0, screw));
    part.solid.cylinder_cuts.push_back(
        hole(0, V(0, y0 - t - d.cell_gap - from_end, w / 2), Lh, Lh + t, screw));
  }
  part.settings.fill_percent = 100;
  part.settings.fill_pattern = "rectilinear";
  part.settings.orientation =
      "on its side, the L's profile on the bed: the corner's bending pulls along the filaments, "
      "not across the "
      "layers; solid, as it sits in the path the tip's vibration takes to the cells";
  part.dimensions = {{"normal cell flange (x)", Lh},
                     {"tangential cell flange (down)", b.vertical},
                     {"plates", t},
                     {"width", w},
                     {"contact pad (the cell's end block)", d.cell_end_block},
                     {"cell screw holes (M5)", screw},
                     {"hole spacing", d.cell_hole_spacing},
                     {"first hole from the cell's end", d.cell_hole_from_end}};
  part.hardware = {
      "4 × M5 × 12 screws into the cells' threaded ends (check yours: some ends are M4)"};
  return part;
}

// ---- the tool holder: a block with the tool's bore and two set screws, a plate up to the cell
// ---- Printed upright, as used: the bore is vertical, so it comes out round and square to the bed
// the disc stands for. The plate's root then has its layers across the friction's bending, at about
// a hundredth of what PETG's layers hold (1 N on 20 mm against a 6 × 17 mm section: 0.2 MPa).
struct HolderLayout {
  double bore, bore_x, block_x, y_back, y_front, block_h, plate_t, plate_w, plate_h;
};

HolderLayout holder_layout(const RigPartDimensions& d) {
  HolderLayout h{};
  h.bore = bore_diameter(d);
  h.plate_t = flange(d);
  // The tool runs on up past the block: its bore lies wholly in front of the plate and the cell.
  h.bore_x = h.plate_t + d.cell_gap + h.bore / 2;
  h.block_x = h.bore_x + h.bore / 2 + d.wall;
  h.y_back = -(h.bore / 2 + d.wall);
  h.y_front = h.bore / 2 + kSetScrewWeb + insert_pocket_depth(d);
  h.block_h = 2 * d.tool_max_diameter;  // a bore twice the tool's diameter long holds it square
  h.plate_w = d.cell_section + 0.004;
  h.plate_h = d.cell_gap + d.cell_hole_from_end + d.cell_hole_spacing +
              clearance_hole(d.cell_screw, d) / 2 + d.wall;
  return h;
}

void add_set_screw(PrintedPart& part, const RigPartDimensions& d, V bore_axis_at, double y_front) {
  // From the front face: the insert's pocket, then the screw's clearance through the web into the
  // bore.
  const double pocket_bottom = y_front - insert_pocket_depth(d);
  part.solid.cylinder_cuts.push_back(
      pocket(1, bore_axis_at, y_front, -insert_pocket_depth(d), d.insert_hole));
  CsgCylinder through{V(bore_axis_at.x(), pocket_bottom + kPartsCutOverrun, bore_axis_at.z()),
                      V(0, -(pocket_bottom + kPartsCutOverrun - bore_axis_at.y()), 0),
                      clearance_hole(d.set_screw, d) / 2};
  part.solid.cylinder_cuts.push_back(through);
}

PrintedPart tool_holder(const RigPartDimensions& d) {
  const HolderLayout h = holder_layout(d);
  const double screw = clearance_hole(d.cell_screw, d);
  PrintedPart part;
  part.name = "tool_holder";
  part.title = "tool holder";
  part.purpose = "clamps a Ø6–12 mm tool square to the disc under the tangential cell's free end";
  const double cx = h.bore_x;
  part.solid.boxes = {
      box({0, h.y_back, 0}, {h.block_x, h.y_front, h.block_h}),
      box({0, -h.plate_w / 2, h.block_h}, {h.plate_t, h.plate_w / 2, h.block_h + h.plate_h})};
  part.solid.cylinder_cuts = {hole(2, V(cx, 0, 0), 0, h.block_h, h.bore)};
  for (double z : {h.block_h / 4, 3 * h.block_h / 4})
    add_set_screw(part, d, V(cx, 0, z), h.y_front);
  for (double from_end : {d.cell_hole_from_end, d.cell_hole_from_end + d.cell_hole_spacing})
    part.solid.cylinder_cuts.push_back(
        hole(0, V(0, 0, h.block_h + d.cell_gap + from_end), 0, h.plate_t, screw));
  part.settings.fill_percent = 100;
  part.settings.fill_pattern = "rectilinear";
  part.settings.orientation =
      "upright, as used: the tool's bore prints vertical, round and square to the bed; solid, in "
      "the path the "
      "tip's vibration takes";
  part.dimensions = {{"tool bore (Ø6–12 mm tools)", h.bore},
                     {"bore axis ahead of the cell's face", h.bore_x},
                     {"bore length", h.block_h},
                     {"set screw inserts (M3 heat-set)", d.insert_hole},
                     {"insert pocket depth", insert_pocket_depth(d)},
                     {"set screws above the bottom", h.block_h / 4},
                     {"cell screw holes (M5)", screw},
                     {"plate", h.plate_t},
                     {"plate height", h.plate_h}};
  part.hardware = {"2 × M3 heat-set insert, pressed in with a soldering iron",
                   "2 × M3 × 8 nylon-tipped set screw",
                   "2 × M5 × 12 screw into the tangential cell's free end"};
  return part;
}

// ---- the accelerometer's mount: a collar on the tool below the holder, a pad on its side ----
// Upright as used: the bore vertical, the pad a wall standing on the bed, the lip at its foot.
// The pad faces across the track, so the board's in-plane sensing axis lies along it.
struct MountLayout {
  double bore, half_x, y_back, y_front, collar_h, pad_t, pad_w, pad_h;
};

MountLayout mount_layout(const RigPartDimensions& d) {
  MountLayout m{};
  m.bore = bore_diameter(d);
  m.half_x = m.bore / 2 + d.wall;
  m.y_back = -(m.bore / 2 + d.wall);
  m.y_front = m.bore / 2 + kSetScrewWeb + insert_pocket_depth(d);
  m.collar_h = d.insert_hole + 2 * d.wall;
  m.pad_t = 0.6 * d.wall;
  m.pad_w = d.board_width + 0.002;
  m.pad_h = kBoardLipHeight + d.board_height;
  return m;
}

PrintedPart accelerometer_mount(const RigPartDimensions& d) {
  const MountLayout m = mount_layout(d);
  PrintedPart part;
  part.name = "accelerometer_mount";
  part.title = "accelerometer mount";
  part.purpose =
      "holds the EVAL-ADXL1002Z board on the tool just below the holder, its sensing axis along "
      "the track";
  const double pad_back = m.y_back - m.pad_t;
  part.solid.boxes = {
      box({-m.half_x, m.y_back, 0}, {m.half_x, m.y_front, m.collar_h}),
      box({-m.pad_w / 2, pad_back, 0}, {m.pad_w / 2, m.y_back, m.pad_h}),
      box({-m.pad_w / 2, pad_back - kBoardLipDepth, 0}, {m.pad_w / 2, pad_back, kBoardLipHeight})};
  part.solid.cylinder_cuts = {hole(2, V(0, 0, 0), 0, m.collar_h, m.bore)};
  add_set_screw(part, d, V(0, 0, m.collar_h / 2), m.y_front);
  part.settings.fill_percent = 100;
  part.settings.fill_pattern = "rectilinear";
  part.settings.orientation =
      "upright, as used: the bore vertical, the pad a wall on the bed with its lip at the foot; "
      "solid, so that "
      "the board reads the tool and not a springy mount";
  part.dimensions = {
      {"tool bore", m.bore},   {"collar height", m.collar_h}, {"pad (board width + 2 mm)", m.pad_w},
      {"pad height", m.pad_h}, {"pad thickness", m.pad_t},    {"lip", kBoardLipDepth}};
  part.hardware = {"1 × M3 heat-set insert and an M3 × 8 nylon-tipped set screw",
                   "the EVAL-ADXL1002Z board glued on the pad (cyanoacrylate, or wax to remove "
                   "it), standing on the lip"};
  return part;
}

}  // namespace

double clearance_hole(double screw_diameter, const RigPartDimensions& d) {
  // ISO 273, medium series.
  static constexpr std::pair<double, double> kIso273Medium[] = {
      {0.003, 0.0034}, {0.004, 0.0045}, {0.005, 0.0055}, {0.006, 0.0066}};
  for (const auto& [nominal, clearance] : kIso273Medium)
    if (std::abs(screw_diameter - nominal) < 1e-6) return clearance + d.hole_shrink;
  throw std::invalid_argument("rig parts: screw " + mm(screw_diameter) +
                              " is not M3, M4, M5 or M6");
}

double pivot_height(const RigPartDimensions& d) {
  const double bracket_drop = flange(d) + d.cell_gap;  // the pad's top to the tangential cell's top
  const double holder = d.cell_gap + holder_layout(d).block_h;
  return d.disc_surface_height + d.arm_height / 2 + d.cell_spacer + d.cell_section + bracket_drop +
         d.cell_length + holder + mount_layout(d).collar_h + d.tool_stick_out;
}

double post_extrusion_length(const RigPartDimensions& d) {
  const PostLayout p = post_layout(d);
  return pivot_height(d) - (p.bore_y - p.screw_zone);
}

double post_rim_clearance(const RigPartDimensions& d) {
  // Seen from above, the disc's axis at the origin, the arm along +x on the line y = −track
  // radius, the pivot 150 mm behind the tip; the post on the side away from the axis.
  const PostLayout p = post_layout(d);
  const double px = -d.tip_ahead_of_pivot;
  const double near_y = -d.track_radius - d.arm_width / 2 - d.pin_washer;
  const double x = std::clamp(0.0, px - p.width / 2, px + p.width / 2);
  const double y = std::clamp(0.0, near_y - p.thickness, near_y);
  return std::hypot(x, y) - d.disc_radius;
}

std::vector<PrintedPart> rig_printed_parts(const RigPartDimensions& d) {
  require_part(post_rim_clearance(d) >= d.fixed_clearance, "arm_post",
               "stands " + mm(post_rim_clearance(d)) + " from the disc's rim, under the " +
                   mm(d.fixed_clearance) + " HARDWARE.md asks between the disc and anything fixed");
  return {arm_post(d), bearing_bridge(d), cell_bracket(d), tool_holder(d), accelerometer_mount(d)};
}

}  // namespace nibrig::rig
