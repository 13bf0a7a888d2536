// The printed tools' designs: derived from the bundled 2 mm VeroClear stylus, they must agree
// with the bundled designs written by hand for the same tools (independent files), without
// meshing anything.
#include "model/forcing/printed_tool_design.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

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

TEST_F(PrintedToolDesign, ALabsMaterialIsTheWholeToolDampedAsItselfWhenItsDampingIsKnown) {
  const PrintedTip pla = printed_tip_of("PLA", materials);
  EXPECT_TRUE(pla.whole_tool);
  EXPECT_EQ(pla.material, "PLA");
  EXPECT_EQ(printed_tip_of("pla", materials).material, "PLA");  // as the table names it
  const mech::Design whole = printed_tool_design(pla, 0.001, template_design, materials);
  EXPECT_EQ(whole.region_materials, (std::map<std::string, std::string>{{"body", "PLA"}}));
  EXPECT_DOUBLE_EQ(std::get<mech::StylusGeometry>(whole.shape).tip_insert_length, 0.0);
  // The datasheet PLA has no damping: the template's (VeroClear's fitted Rayleigh damping) holds.
  ASSERT_TRUE(whole.damping.has_value());
  EXPECT_DOUBLE_EQ(whole.damping->stiffness,
                   mech::design_damping(template_design, materials).first.stiffness);
  // A ring-down calibration gives a material its own damping: the whole print takes it.
  std::vector<mech::Material> all = materials.materials();
  mech::Material lab = materials.find("PLA");
  lab.name = "PLA-lab";
  lab.damping = mech::RayleighDamping{3.0, 2.0e-6};
  all.push_back(lab);
  const mech::MaterialTable with_lab(std::move(all));
  const mech::Design damped =
      printed_tool_design(printed_tip_of("PLA-lab", with_lab), 0.004, template_design, with_lab);
  EXPECT_EQ(damped.region_materials.at("body"), "PLA-lab");
  EXPECT_DOUBLE_EQ(damped.damping->mass, 3.0);
  EXPECT_DOUBLE_EQ(damped.damping->stiffness, 2.0e-6);
  // The paper's names keep their own designs with a table too.
  EXPECT_FALSE(printed_tip_of("DM95", materials).whole_tool);
  EXPECT_EQ(printed_tip_of("vero", materials).material, "VeroClear-Piovarci2018");
}

TEST_F(PrintedToolDesign, AMaterialNoTableHoldsHasNoDesignAndIsNamed) {
  try {
    printed_tip_of("unobtainium", materials);
    FAIL() << "an unknown material has no design";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'unobtainium'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("PLA"), std::string::npos)
        << e.what();  // what the table has
  }
  EXPECT_FALSE(has_printed_design("unobtainium", materials));
  EXPECT_TRUE(has_printed_design("TPU-95A", materials));
  EXPECT_FALSE(has_printed_design("TPU-95A", mech::MaterialTable{}));  // the paper's alone
}

}  // namespace
}  // namespace nibrig::model::forcing
