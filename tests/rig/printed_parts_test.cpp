// The rig's printed parts as solids: each part's meshed volume against its boxes less its holes
// worked out by hand from the rig's figures, closed and outward-wound surfaces, the sizes that
// matter to a fitter (the bearing seat, the tool's bore, the pivot's height), and the files.
#include "rig/printed_parts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "model/mechanics/region_surface.hpp"
#include "rig/printed_parts_drawing.hpp"
#include "rig/printed_parts_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

using std::numbers::pi;
const RigPartDimensions kDims;

// Meshing the five parts takes seconds (more under the sanitizers): once a process.
const std::vector<MeshedPart>& meshed_parts() {
  static const std::vector<MeshedPart> parts = [] {
    std::vector<MeshedPart> out;
    for (const auto& p : rig_printed_parts(kDims)) out.push_back(mesh_printed_part(p));
    return out;
  }();
  return parts;
}

const MeshedPart& meshed(const std::string& name) {
  for (const auto& m : meshed_parts())
    if (m.part.name == name) return m;
  throw std::logic_error("no part " + name);
}

double cylinder(double diameter, double length) { return pi * diameter * diameter / 4 * length; }
// ISO 273 medium clearance, restated here so that the library's table is checked, not trusted.
double m3_clearance() { return 0.0034 + kDims.hole_shrink; }
double m5_clearance() { return 0.0055 + kDims.hole_shrink; }
double m6_clearance() { return 0.0066 + kDims.hole_shrink; }

// What a set screw's Ø a hole, ending on the axis of a bore of radius R across it, takes out
// beyond the plane tangent to the bore: ∫ chord(x) · (R − √(R² − x²)) dx, by Simpson's rule.
double lens_beyond_tangent(double a, double R) {
  constexpr int n = 2000;
  const double h = 2 * a / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double x = -a + i * h;
    const double f = 2 * std::sqrt(std::max(0.0, a * a - x * x)) * (R - std::sqrt(R * R - x * x));
    sum += f * (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2));
  }
  return sum * h / 3;
}

// A set screw from the front face: the insert's pocket (5.7 mm insert + 0.8 mm), the 1.5 mm web
// the screw passes, and the sliver up to the bore's round wall.
double set_screw_volume(double bore) {
  return cylinder(kDims.insert_hole, kDims.insert_length + 0.0008) +
         cylinder(m3_clearance(), 0.0015) + lens_beyond_tangent(m3_clearance() / 2, bore / 2);
}

// The part as drawn: boxes less holes, from the rig's figures (rig/printed_parts.cpp's layout
// restated, so that a hole moved into another, or out of the material, shows).
std::map<std::string, double> closed_form_volumes() {
  const auto& d = kDims;
  std::map<std::string, double> v;
  const double seat = d.pivot_bearing_od + d.press_fit_allowance;
  {
    const double W = 2 * d.extrusion_side, T = 3 * d.pivot_bearing_width;
    const double H =
        2 * d.extrusion_side + d.pin_diameter + d.post_adjustment + seat / 2 + 1.5 * d.wall;
    const double through = (d.pin_diameter + d.pivot_bearing_od) / 2;
    v["arm_post"] = W * H * T - 2 * cylinder(seat, d.pivot_bearing_width) -
                    cylinder(through, d.pivot_bearing_width) - 2 * cylinder(m5_clearance(), T);
  }
  {
    const double inner = d.flange_bearing_length + 0.012, leg = m5_clearance() + 2 * d.wall + 0.002;
    const double length = inner + 2 * leg, depth = d.flange_bearing_boss + 4 * d.wall,
                 deck = 2 * d.wall;
    const double h = d.bearing_spacing;
    v["bearing_bridge"] = length * depth * deck + 2 * leg * depth * (h - deck) -
                          cylinder(d.flange_bearing_boss, deck) -
                          2 * cylinder(m6_clearance(), deck) - 4 * cylinder(m5_clearance(), h);
  }
  {
    const double t = 1.5 * d.wall, w = d.cell_section + 0.004;
    const double Lh = d.cell_hole_from_end + d.cell_hole_spacing + m5_clearance() / 2 + d.wall;
    const double Lv =
        t + d.cell_gap + d.cell_hole_from_end + d.cell_hole_spacing + m5_clearance() / 2 + d.wall;
    const double relief = 0.001;
    v["cell_bracket"] = (Lh + t) * (t - relief) * w + (d.cell_end_block + t) * relief * w +
                        t * (Lv - t) * w - 4 * cylinder(m5_clearance(), t);
  }
  const double bore = d.tool_max_diameter + d.tool_clearance;
  const double front = bore / 2 + 0.0015 + d.insert_length + 0.0008, back = bore / 2 + d.wall;
  {
    const double t = 1.5 * d.wall, x = t + d.cell_gap + bore + d.wall, hb = 2 * d.tool_max_diameter;
    const double plate_h =
        d.cell_gap + d.cell_hole_from_end + d.cell_hole_spacing + m5_clearance() / 2 + d.wall;
    v["tool_holder"] = x * (front + back) * hb - cylinder(bore, hb) - 2 * set_screw_volume(bore) +
                       t * (d.cell_section + 0.004) * plate_h - 2 * cylinder(m5_clearance(), t);
  }
  {
    const double collar_h = d.insert_hole + 2 * d.wall, pad_w = d.board_width + 0.002;
    v["accelerometer_mount"] = (bore + 2 * d.wall) * (front + back) * collar_h -
                               cylinder(bore, collar_h) - set_screw_volume(bore) +
                               pad_w * 0.6 * d.wall * (0.002 + d.board_height) +
                               pad_w * 0.002 * 0.002;
  }
  return v;
}

// Every curved wall in these parts is a hole; its polygon lies inside the circle, so the mesh
// holds a little more than the drawing: at n facets a circle's area falls short by
// 1 − n·sin(2π/n)/(2π). The mesher is asked for 64 around a circle and sizes by curvature with
// some slack, so the bound is taken at 32: 0.64 % of the holes' volume.
double hole_volume(const PrintedPart& part) {
  double sum = 0;
  for (const auto& c : part.solid.cylinder_cuts) sum += pi * c.radius * c.radius * c.axis.norm();
  return sum;
}

TEST(RigPrintedParts, EachVolumeIsItsBoxesLessItsHoles) {
  const auto expected = closed_form_volumes();
  ASSERT_EQ(meshed_parts().size(), 5u);
  constexpr int kFewestFacets = 32;
  const double deficit = 1 - kFewestFacets * std::sin(2 * pi / kFewestFacets) / (2 * pi);
  for (const auto& m : meshed_parts()) {
    SCOPED_TRACE(m.part.name);
    ASSERT_TRUE(expected.count(m.part.name));
    const double exact = expected.at(m.part.name);
    const double got = model::mechanics::enclosed_volume(m.surface);
    // Only holes are curved: the mesh can only hold more than the drawing, by the polygons' share.
    EXPECT_GE(got, exact * (1 - 1e-9));
    EXPECT_LE(got - exact, deficit * hole_volume(m.part))
        << "got " << got * 1e9 << " mm3, drawn " << exact * 1e9;
  }
}

TEST(RigPrintedParts, EverySurfaceIsClosedAndWoundOutward) {
  for (const auto& m : meshed_parts()) {
    SCOPED_TRACE(m.part.name);
    const auto& s = m.surface;
    // Each directed edge once, and its reverse once: every edge joins exactly two triangles, and
    // they agree on the winding.
    std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
    for (const auto& t : s.triangles)
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(directed.insert({t[k], t[(k + 1) % 3]}).second);
    for (const auto& [a, b] : directed) ASSERT_TRUE(directed.count({b, a})) << a << "-" << b;
    EXPECT_GT(model::mechanics::enclosed_volume(s), 0.0);  // counter-clockwise from outside
  }
}

TEST(RigPrintedParts, BoundingBoxesStandOnTheBedAndFitIt) {
  const auto& d = kDims;
  const double seat = d.pivot_bearing_od + d.press_fit_allowance;
  const std::map<std::string, std::array<double, 3>> sizes = {
      {"arm_post",
       {2 * d.extrusion_side,
        2 * d.extrusion_side + d.pin_diameter + d.post_adjustment + seat / 2 + 1.5 * d.wall,
        3 * d.pivot_bearing_width}},
      {"bearing_bridge",
       {d.flange_bearing_length + 0.012 + 2 * (m5_clearance() + 2 * d.wall + 0.002),
        d.flange_bearing_boss + 4 * d.wall, d.bearing_spacing}},
  };
  for (const auto& m : meshed_parts()) {
    SCOPED_TRACE(m.part.name);
    std::array<double, 3> lo{1, 1, 1}, hi{-1, -1, -1};
    for (const auto& v : m.surface.vertices)
      for (std::size_t k = 0; k < 3; ++k)
        lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    EXPECT_NEAR(lo[2], 0.0, 1e-9);                                      // on the bed, as it prints
    for (std::size_t k = 0; k < 3; ++k) EXPECT_LT(hi[k] - lo[k], 0.2);  // the 200 mm bed
    if (sizes.count(m.part.name))  // flat faces are meshed exactly: to rounding
      for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(hi[k] - lo[k], sizes.at(m.part.name)[k], 1e-9) << k;
  }
}

// The vertices on a hole's wall between two heights: their distances from its axis.
std::vector<double> radii_near_axis(const model::io::SurfaceMesh& s, double cx, double cy,
                                    double z0, double z1, double within) {
  std::vector<double> out;
  for (const auto& v : s.vertices) {
    const double r = std::hypot(v[0] - cx, v[1] - cy);
    if (v[2] > z0 && v[2] < z1 && r < within) out.push_back(r);
  }
  return out;
}

TEST(RigPrintedParts, TheBearingSeatsAndTheToolBoreAreTheirDrawnSize) {
  const auto& d = kDims;
  const double seat = d.pivot_bearing_od + d.press_fit_allowance;
  const double bore_y = 2 * d.extrusion_side + d.pin_diameter + d.post_adjustment;
  // Inside the first seat's depth (clear of its floor and mouth) only the seat's wall lies within
  // 11 mm of the pin's axis: every vertex there is on the Ø19.1 mm circle, to rounding.
  const auto seat_radii = radii_near_axis(meshed("arm_post").surface, d.extrusion_side, bore_y,
                                          1e-4, d.pivot_bearing_width - 1e-4, 0.011);
  ASSERT_GE(seat_radii.size(), 32u);
  for (double r : seat_radii) EXPECT_NEAR(r, seat / 2, 1e-7);
  // The tool's bore: Ø12.6 mm, the largest tool with 0.6 mm to spare before the print shrinks it.
  const double bore = d.tool_max_diameter + d.tool_clearance;
  const double bore_x =
      1.5 * d.wall + d.cell_gap + bore / 2;  // clear of the plate: the tool runs on up
  const auto bore_radii = radii_near_axis(meshed("tool_holder").surface, bore_x, 0, 1e-4,
                                          2 * d.tool_max_diameter - 1e-4, bore / 2 + 1e-4);
  ASSERT_GE(bore_radii.size(), 32u);
  for (double r : bore_radii) EXPECT_GE(r, bore / 2 - 1e-7);  // nothing narrows the bore
  // A pencil runs on up past the block: nothing of the holder stands over the bore.
  EXPECT_TRUE(radii_near_axis(meshed("tool_holder").surface, bore_x, 0,
                              2 * d.tool_max_diameter + 1e-6, 1.0, bore / 2 - 1e-6)
                  .empty());
  EXPECT_NEAR(*std::min_element(bore_radii.begin(), bore_radii.end()), bore / 2, 1e-7);
}

TEST(RigPrintedParts, ThePivotLevelsTheArmAndThePostClearsTheRim) {
  const auto& d = kDims;
  // Disc surface, then from the pivot down: half the arm, spacer, normal cell, bracket plate and
  // gap, tangential cell, gap and holder block, collar, the tool's stick-out.
  const double chain = d.arm_height / 2 + d.cell_spacer + d.cell_section + 1.5 * d.wall +
                       d.cell_gap + d.cell_length + d.cell_gap + 2 * d.tool_max_diameter +
                       (d.insert_hole + 2 * d.wall) + d.tool_stick_out;
  EXPECT_NEAR(pivot_height(d), d.disc_surface_height + chain, 1e-12);
  EXPECT_NEAR(pivot_height(d), 0.2357, 1e-6);  // 70 + 165.7 mm with the documented figures
  // The post's corner nearest the axis: 130 mm back along the tangent, 66 mm out from the track.
  EXPECT_NEAR(post_rim_clearance(d), std::hypot(0.130, 0.066) - d.disc_radius, 1e-12);
  EXPECT_GE(post_rim_clearance(d), d.fixed_clearance);
  RigPartDimensions short_arm = d;
  short_arm.tip_ahead_of_pivot = 0.090;  // the post would stand over the disc
  try {
    rig_printed_parts(short_arm);
    ADD_FAILURE() << "a post over the disc was made";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("arm_post"), std::string::npos) << e.what();
  }
  EXPECT_THROW(clearance_hole(0.0025, d), std::invalid_argument);
}

TEST(RigPrintedParts, SettingsAndDrawingsComeFromThePart) {
  for (const auto& part : rig_printed_parts(kDims)) {
    SCOPED_TRACE(part.name);
    std::map<std::string, std::string> ini;
    std::istringstream lines(prusa_slicer_ini(part));
    for (std::string l; std::getline(lines, l);)
      if (const auto eq = l.find(" = "); eq != std::string::npos && l[0] != '#')
        ini[l.substr(0, eq)] = l.substr(eq + 3);
    EXPECT_EQ(ini.at("perimeters"), "4");  // strength sits in the walls around every hole
    EXPECT_GE(std::stoi(ini.at("fill_density")), 40);
    EXPECT_EQ(ini.at("support_material"), "0");  // every part is laid so that nothing overhangs far
    EXPECT_EQ(ini.at("filament_type"), "PETG");
    const std::string svg = part_drawing_svg(part);
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    for (const auto& dim : part.dimensions)
      EXPECT_NE(svg.find(dim.label), std::string::npos) << dim.label;
  }
  const auto parts = rig_printed_parts(kDims);
  const std::string post = part_drawing_svg(parts.front());
  EXPECT_NE(post.find(">19.1<"),
            std::string::npos);  // the seat's diameter as the drawing states it
  EXPECT_NE(post.find(">235.7<"), std::string::npos);  // the pivot's height
}

// HARDWARE.md shows the drawings committed in rig/parts/: they are what the parts draw now, byte for
// byte, so a change of a part's figures changes its picture in the guide too.
TEST(RigPrintedParts, TheGuidesDrawingsAreThePartsOwn) {
  for (const PrintedPart& part : rig_printed_parts()) {
    const std::filesystem::path committed =
        std::filesystem::path(NIBRIG_SOURCE_DIR) / "rig" / "parts" / (part.name + ".svg");
    std::ifstream in(committed, std::ios::binary);
    ASSERT_TRUE(in) << committed << " is missing: nibrig rig parts -o DIR writes it";
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, part_drawing_svg(part)) << committed << " differs from the part: copy it from nibrig rig parts -o DIR";
  }
}

TEST(RigPrintedParts, WritingLeavesOtherFilesAndRefusesAFileForAFolder) {
  const auto dir = nibrig::test::scratch_dir("rig_printed_parts");
  std::ofstream(dir / "notes.txt") << "mine";
  // Coarse facets: this checks the files and the folder, not the geometry the tests above hold.
  const model::mechanics::CsgMeshing coarse{12e-3, 16};
  const auto written = write_rig_parts(dir, kDims, coarse);
  ASSERT_EQ(written.parts.size(), 5u);
  for (const auto& f : written.parts)
    for (const auto& file : {f.three_mf, f.stl, f.ini, f.drawing})
      EXPECT_GT(std::filesystem::file_size(file), 0u) << file;
  std::ifstream notes(dir / "notes.txt");
  std::string kept;
  std::getline(notes, kept);
  EXPECT_EQ(kept, "mine");
  EXPECT_EQ(written.recipe_json["parts"].size(), 5u);
  EXPECT_NEAR(written.recipe_json["rig"]["pivot_height_mm"].get<double>(), 235.7, 1e-6);
  try {
    write_rig_parts(dir / "notes.txt", kDims, coarse);
    ADD_FAILURE() << "wrote into a file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("notes.txt"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::rig
