// A lab's material in a design point: the template stylus printed whole of it (as an FDM or SLA
// printer makes a stylus), never mixed, and a designer's one-material stylus read back as that
// material's point.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <stdexcept>
#include <string>

#include "model/design/design_point.hpp"
#include "model/design/mixed_design.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

namespace mech = model::mechanics;

class LabMaterialDesign : public ::testing::Test {
 protected:
  mech::MaterialTable materials =
      mech::read_material_table(nibrig::test::assets_dir() / "materials.json");
  mech::Design template_design = mech::read_design(
      nibrig::test::assets_dir() / "designs" / "stylus_vero_tip2mm.json", materials);
};

std::string refusal_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST_F(LabMaterialDesign, APointOfOneLabMaterialIsTheWholeStylusOfIt) {
  const MixedDesign petg =
      mixed_design(parse_design_point("PETG,tip=1.5mm"), template_design, materials);
  EXPECT_EQ(petg.design.region_materials, (std::map<std::string, std::string>{{"body", "PETG"}}));
  const auto& stylus = std::get<mech::StylusGeometry>(petg.design.shape);
  EXPECT_DOUBLE_EQ(stylus.tip_diameter, 0.0015);
  EXPECT_DOUBLE_EQ(stylus.tip_insert_length, 0.0);
  // Read back: the designer's file of that stylus is the same point.
  const DesignPoint back = design_point_of(petg.design);
  ASSERT_EQ(back.mix.size(), 1u);
  EXPECT_EQ(back.mix.front().material, "PETG");
  EXPECT_DOUBLE_EQ(back.tip_diameter_m, 0.0015);
}

TEST_F(LabMaterialDesign, ALabMaterialIsNeverMixedAndTheRefusalNamesIt) {
  const std::string said = refusal_of([&] {
    mixed_design(parse_design_point("PLA:0.5,DM85:0.5,tip=2mm"), template_design, materials);
  });
  EXPECT_NE(said.find("'PLA'"), std::string::npos) << said;
  EXPECT_NE(said.find("whole tool"), std::string::npos) << said;
  // A material no table holds is named with what the table has.
  const std::string unknown = refusal_of(
      [&] { mixed_design(parse_design_point("unobtainium,tip=2mm"), template_design, materials); });
  EXPECT_NE(unknown.find("'unobtainium'"), std::string::npos) << unknown;
}

TEST_F(LabMaterialDesign, AStylusWithATipOfAnotherMaterialThatIsNotThePapersIsRefused) {
  mech::Design two = template_design;
  auto geometry = std::get<mech::StylusGeometry>(two.shape);
  geometry.tip_insert_length = 0.006;
  two.shape = geometry;
  two.region_materials = {{"body", "PLA"}, {"tip", "TPU-95A"}};
  const std::string said = refusal_of([&] { design_point_of(two); });
  EXPECT_NE(said.find("'TPU-95A'"), std::string::npos) << said;
}

}  // namespace
}  // namespace nibrig::model::design
