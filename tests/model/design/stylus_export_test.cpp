// A design point made printable: the stylus its prediction simulates, region by region, with what
// the printer mixes; refused designs and folders write nothing; and the exported 3MF, imported
// back through the mesh import and solved, gives the design's modes.
#include "model/design/stylus_export.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "model/design/mixed_design.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/mechanics/region_surface.hpp"
#include "model/mesh_io/stylus_3mf.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

// The bundled template and materials at 8 modes: the first three are what the tests compare.
PredictionSetup export_setup() {
  PredictionSetup setup;
  setup.materials = mechanics::read_material_table(io::default_materials());
  setup.template_design = mechanics::read_design(io::default_stylus_design(), setup.materials);
  setup.modes = 8;
  return setup;
}

const StylusRegion& region_named(const StylusPrint& print, const std::string& name) {
  for (const auto& r : print.regions)
    if (r.surface.name == name) return r;
  throw std::runtime_error("no region " + name);
}

TEST(StylusExport, AMixedTipIsItsOwnRegionWithTheFractionsToMix) {
  const auto point = parse_design_point("DM85:0.62,vero:0.38,tip=2.7mm");
  const auto print = stylus_print(export_setup(), point);
  ASSERT_EQ(print.regions.size(), 2u);
  const auto& tip = region_named(print, "tip");
  ASSERT_EQ(tip.mix.size(), 2u);
  EXPECT_EQ(tip.mix[0].material, "DM85");
  EXPECT_DOUBLE_EQ(tip.mix[0].fraction, 0.62);
  EXPECT_EQ(tip.mix[1].material, "vero");
  EXPECT_DOUBLE_EQ(tip.mix[1].fraction, 0.38);
  const auto& body = region_named(print, "body");
  ASSERT_EQ(body.mix.size(), 1u);
  EXPECT_EQ(body.mix[0].material, "vero");
  EXPECT_EQ(body.material, "VeroClear-Piovarci2018");
  // The tip's apex is where the design puts it: the template's body and taper plus the tip's radius.
  double apex = 0;
  for (const auto& v : tip.surface.vertices) apex = std::max(apex, v[0]);
  const auto& stylus = std::get<mechanics::StylusGeometry>(print.design.shape);
  EXPECT_NEAR(stylus.tip_diameter, 0.0027, 1e-15);
  EXPECT_NEAR(apex, stylus.overall_length(), 1e-9);  // a node at the apex, on the geometry
}

TEST(StylusExport, ASingleMaterialWithoutAnInsertIsOneRegion) {
  const auto print = stylus_print(export_setup(), parse_design_point("vero,tip=2mm"));
  ASSERT_EQ(print.regions.size(), 1u);
  EXPECT_EQ(print.regions[0].surface.name, "body");
  EXPECT_EQ(print.regions[0].mix.size(), 1u);
}

TEST(StylusExport, ADesignOutsideTheTableOrTheGeometryIsRefusedNamingIt) {
  const auto setup = export_setup();
  try {
    stylus_print(setup, parse_design_point("wood,tip=2mm"));
    FAIL() << "a material outside the table was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("wood"), std::string::npos) << e.what();
  }
  // A tip wider than the 10 mm body.
  EXPECT_THROW(stylus_print(setup, parse_design_point("vero,tip=12mm")), std::invalid_argument);
}

TEST(StylusExport, AFolderThatCannotBeWrittenIsRefusedAndNothingIsWritten) {
  const auto dir = nibrig::test::scratch_dir("stylus_export_refusal");
  std::ofstream(dir / "a_file") << "not a folder";
  const auto print = stylus_print(export_setup(), parse_design_point("vero,tip=2mm"));
  try {
    write_stylus_files(dir / "a_file" / "out" / "stylus.3mf", print);
    FAIL() << "wrote into a file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a_file"), std::string::npos) << e.what();
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
}

// Exported, imported back through the mesh import (the 3MF's objects as regions, their triangles
// kept) and solved with the same materials, clamp box, probes and element size (the test's 6 mm,
// to keep the solves short): the design's first three modes, within three things that part them,
// each measured here from the meshes:
//  - faceting: the printed surface is flat between the FEM's nodes, so the solid is a little
//    thinner than the curved one the FEM solved. For a round rod a bending frequency goes as the
//    radius, whose relative deficit is half the volume's (V ∝ r²);
//  - the clamp's edge: the design is meshed with a node plane at the grip and clamped up to it;
//    the re-meshed solid has none, so its clamped nodes stop short of the plane, by at most the
//    largest gap between the plane and a clamped corner of an element it cuts. A cantilever's
//    frequencies go as its free length to the −2: 2 · gap / free length;
//  - discretisation: two meshes of one shape at one element size differ by up to twice the error
//    of either, estimated from the design solved on elements 1/√2 as large.
TEST(StylusExport, TheExported3mfImportedBackGivesTheDesignsFirstThreeModes) {
  const auto dir = nibrig::test::scratch_dir("stylus_export_modes");
  auto setup = export_setup();
  setup.mesh_size = 0.006;
  const auto print = stylus_print(setup, parse_design_point("DM85:0.62,vero:0.38,tip=2.7mm"));
  const auto files = write_stylus_files(dir / "stylus.3mf", print);
  const auto designed = mechanics::build_design_model(print.design, print.materials);
  mechanics::Design finer = print.design;
  finer.mesh_size = print.design.mesh_size / std::sqrt(2.0);
  const auto refined = mechanics::build_design_model(finer, print.materials);

  const auto& stylus = std::get<mechanics::StylusGeometry>(print.design.shape);
  mechanics::Design imported = print.design;
  mechanics::MeshFileShape shape;
  shape.path = files.three_mf;
  shape.clamp_box = std::make_pair(Eigen::Vector3d(-1.0, -1.0, -1.0), Eigen::Vector3d(stylus.grip_length, 1.0, 1.0));
  imported.shape = shape;
  const auto back = mechanics::build_design_model(imported, print.materials);
  ASSERT_EQ(back.mesh.region_names.size(), 2u);

  double surface_volume = 0;
  for (const auto& r : print.regions) surface_volume += mechanics::enclosed_volume(r.surface);
  const double r_body = stylus.body_diameter / 2, r_tip = stylus.tip_diameter / 2;
  const double true_volume =
      std::numbers::pi * (r_body * r_body * stylus.body_length +
                          stylus.taper_length / 3 * (r_body * r_body + r_body * r_tip + r_tip * r_tip) +
                          2.0 / 3.0 * r_tip * r_tip * r_tip);
  const double faceting = (true_volume - surface_volume) / (2 * true_volume);
  ASSERT_GT(faceting, 0.0);

  const auto& mesh = back.mesh;
  std::vector<bool> held(static_cast<std::size_t>(mesh.nodes.cols()), false);
  for (int node : mesh.node_sets.at("clamp")) held[static_cast<std::size_t>(node)] = true;
  double gap = 0;
  for (const auto& t : mesh.tets) {
    int clamped = 0;
    for (int c = 0; c < 4; ++c) clamped += held[static_cast<std::size_t>(t[c])] ? 1 : 0;
    if (clamped == 0 || clamped == 4) continue;
    for (int c = 0; c < 4; ++c)
      if (held[static_cast<std::size_t>(t[c])]) gap = std::max(gap, stylus.grip_length - mesh.nodes(0, t[c]));
  }
  const double clamp_edge = 2 * gap / (stylus.overall_length() - stylus.grip_length);

  for (std::size_t k = 0; k < 3; ++k) {
    const double f = designed.modal.omega[k], f_fine = refined.modal.omega[k], f_back = back.modal.omega[k];
    const double discretisation = 2 * std::abs(f - f_fine) / f;
    EXPECT_NEAR(f_back / f, 1.0, faceting + clamp_edge + discretisation)
        << "mode " << k + 1 << ": designed " << f / (2 * std::numbers::pi) << " Hz, imported "
        << f_back / (2 * std::numbers::pi) << " Hz; faceting " << faceting << ", clamp edge " << clamp_edge
        << ", discretisation " << discretisation;
  }
}

}  // namespace
}  // namespace nibrig::model::design
