#include "model/catalog/tool_names.hpp"

#include <gtest/gtest.h>

namespace nibrig::model::catalog {
namespace {

TEST(DescribeTool, NamesRealCommercialAndPrintedTools) {
  EXPECT_EQ(describe_tool("p2h").name, "2H pencil");
  EXPECT_EQ(describe_tool("p2h").kind, "real");
  EXPECT_EQ(describe_tool("apencil").kind, "commercial");
  const auto printed = describe_tool("DM852");
  EXPECT_EQ(printed.kind, "printed");
  EXPECT_EQ(printed.material, "DM85");
  ASSERT_TRUE(printed.tip_diameter_m.has_value());
  EXPECT_DOUBLE_EQ(*printed.tip_diameter_m, 0.002);
  EXPECT_EQ(describe_tool("DM851_nail1").kind, "printed");
  EXPECT_EQ(describe_tool("penh_DM95").material, "DM95");
}

TEST(DescribeTool, NamesALabsOneMaterialPrintByItsMaterialAndTip) {
  const auto pla = describe_tool("PLA-1mm");
  EXPECT_EQ(pla.kind, "printed");
  EXPECT_EQ(pla.material, "PLA");
  ASSERT_TRUE(pla.tip_diameter_m.has_value());
  EXPECT_DOUBLE_EQ(*pla.tip_diameter_m, 0.001);
  // A material whose own name holds '-' and digits, and a tip in tenths of a millimetre.
  const auto tpu = describe_tool("TPU-95A-0.8mm");
  EXPECT_EQ(tpu.material, "TPU-95A");
  EXPECT_DOUBLE_EQ(*tpu.tip_diameter_m, 0.0008);
  // Not a print: no tip in millimetres, or nothing before it.
  EXPECT_EQ(describe_tool("PLA-1").kind, "unknown");
  EXPECT_EQ(describe_tool("-1mm").kind, "unknown");
  EXPECT_EQ(describe_tool("PLA-mm").kind, "unknown");
}

TEST(DescribeTool, KeepsUnknownIdsInsteadOfFailing) {
  const auto unknown = describe_tool("brand_new_nib");
  EXPECT_EQ(unknown.id, "brand_new_nib");
  EXPECT_EQ(unknown.kind, "unknown");
}

TEST(DescribeSurface, NamesThePapersSurfaces) {
  EXPECT_EQ(describe_surface("paperlike").name, "PaperLike screen cover");
  EXPECT_EQ(describe_surface("mystery").name, "mystery");
}

}  // namespace
}  // namespace nibrig::model::catalog
