// The printed tools' designs: derived from the bundled 2 mm VeroClear stylus, they must agree
// with the bundled designs written by hand for the same tools (independent files), without
// meshing anything.
#include "model/forcing/printed_tool_design.hpp"

#include <gtest/gtest.h>

#include "model/mechanics/design_model.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::forcing {
namespace {

namespace mech = model::mechanics;

class PrintedToolDesign : public ::testing::Test {
 protected:
  mech::MaterialTable materials =
      mech::read_material_table(nibrig::test::assets_dir() / "materials.json");
  mech::Design read(const std::string& name) {
    return mech::read_design(nibrig::test::assets_dir() / "designs" / name, materials);
  }
  mech::Design template_design = read("stylus_vero_tip2mm.json");
};

void expect_same_stylus(const mech::Design& a, const mech::Design& b) {
  const auto& sa = std::get<mech::StylusGeometry>(a.shape);
  const auto& sb = std::get<mech::StylusGeometry>(b.shape);
  EXPECT_DOUBLE_EQ(sa.body_length, sb.body_length);
  EXPECT_DOUBLE_EQ(sa.body_diameter, sb.body_diameter);
  EXPECT_DOUBLE_EQ(sa.taper_length, sb.taper_length);
  EXPECT_DOUBLE_EQ(sa.tip_diameter, sb.tip_diameter);
  EXPECT_DOUBLE_EQ(sa.tip_insert_length, sb.tip_insert_length);
  EXPECT_DOUBLE_EQ(sa.grip_length, sb.grip_length);
  EXPECT_EQ(a.region_materials, b.region_materials);
  EXPECT_TRUE(a.tip.point.isApprox(b.tip.point, 1e-12));
  EXPECT_TRUE(a.tip.direction.isApprox(b.tip.direction, 1e-12));
  EXPECT_TRUE(a.sensor.point.isApprox(b.sensor.point, 1e-12));
  EXPECT_TRUE(a.sensor.direction.isApprox(b.sensor.direction, 1e-12));
  EXPECT_DOUBLE_EQ(a.mesh_size, b.mesh_size);
  EXPECT_EQ(a.modes, b.modes);
}

TEST_F(PrintedToolDesign, MatchesTheBundledTwoMaterialStylus) {
  const mech::Design bundled = read("stylus_vero_dm85tip_4mm.json");
  const mech::Design derived =
      printed_tool_design(printed_tip_of("DM85"), 0.004, template_design, materials);
  // The insert length constant comes from this file.
  EXPECT_DOUBLE_EQ(std::get<mech::StylusGeometry>(bundled.shape).tip_insert_length,
                   kPrintedTipInsertLength);
  expect_same_stylus(derived, bundled);
  ASSERT_TRUE(derived.damping.has_value());
  EXPECT_DOUBLE_EQ(derived.damping->stiffness, bundled.damping->stiffness);
  EXPECT_DOUBLE_EQ(derived.damping->mass, bundled.damping->mass);
}

TEST_F(PrintedToolDesign, MatchesEveryBundledDigitalMaterialStylus) {
  for (const std::string material : {"DM95", "DM85"})
    for (const int mm : {1, 2, 4}) {
      const std::string file = "stylus_vero_" + std::string(material == "DM95" ? "dm95" : "dm85") +
                               "tip_" + std::to_string(mm) + "mm.json";
      SCOPED_TRACE(file);
      const mech::Design bundled = read(file);
      const mech::Design derived =
          printed_tool_design(printed_tip_of(material), mm * 1e-3, template_design, materials);
      expect_same_stylus(derived, bundled);
      EXPECT_EQ(bundled.region_materials.at("tip"), material);
    }
}

TEST_F(PrintedToolDesign, MatchesTheBundledOneMaterialStyli) {
  for (const auto& [file, diameter] :
       {std::pair{"stylus_vero_tip1mm.json", 0.001}, std::pair{"stylus_vero_tip4mm.json", 0.004},
        std::pair{"stylus_vero_tip2mm.json", 0.002}}) {
    SCOPED_TRACE(file);
    const mech::Design derived =
        printed_tool_design(printed_tip_of("vero"), diameter, template_design, materials);
    expect_same_stylus(derived, read(file));
    // The damping the one-material file gets from its material, now stated in the design.
    EXPECT_DOUBLE_EQ(derived.damping->stiffness, 1.25e-3);
  }
  // Teflon-taped tools are VeroClear tools (the tape is absorbed by m(f)).
  const auto teflon =
      printed_tool_design(printed_tip_of("teflon"), 0.001, template_design, materials);
  expect_same_stylus(teflon, read("stylus_vero_tip1mm.json"));
}

TEST_F(PrintedToolDesign, RefusesWhatHasNoDesign) {
  EXPECT_THROW(printed_tip_of("graphite"), std::invalid_argument);
  EXPECT_THROW(printed_tip_of(""), std::invalid_argument);
  EXPECT_THROW(printed_tool_design(printed_tip_of("DM95"), 0.0, template_design, materials),
               std::invalid_argument);
  EXPECT_THROW(
      printed_tool_design(printed_tip_of("DM95"), 0.002, read("paper_bar.json"), materials),
      std::invalid_argument);
  EXPECT_EQ(printed_tip_of("DM95").material, "DM95");
  EXPECT_EQ(printed_tool_design(printed_tip_of("DM95"), 0.001, template_design, materials)
                .region_materials.at("tip"),
            "DM95");
}

}  // namespace
}  // namespace nibrig::model::forcing
