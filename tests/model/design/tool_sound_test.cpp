// Making "tool X on surface Y" into what a voice plays: catalog tools through the bundled stylus's
// modes, bad requests refused before any meshing, and the stylus meshed once for every tool.
#include "model/design/tool_sound.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "model/io/catalog_file.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

using ::testing::HasSubstr;

std::string refusal(const ToolSounds& sounds, const std::string& tool, const std::string& surface) {
  try {
    sounds.check(tool, surface);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ToolSound, ADesignPointIsToldFromACatalogToolByItsTip) {
  EXPECT_TRUE(names_design_point("DM85:0.5,vero:0.5,tip=2mm"));
  EXPECT_FALSE(names_design_point("vero2"));
}

TEST(ToolSound, RefusesWhatItCannotPlayBeforeAnyMeshing) {
  const ToolSounds sounds({});
  // The tool exists but not on that surface: say where it does.
  EXPECT_THAT(refusal(sounds, "cryon", "moon"), HasSubstr("it has one on: "));
  EXPECT_THAT(refusal(sounds, "cryon", "moon"), HasSubstr("office"));
  // No such tool: list the tools there are.
  EXPECT_THAT(refusal(sounds, "crayon", "office"), HasSubstr("tools with one: "));
  // A design point with fractions that do not add up.
  EXPECT_THAT(refusal(sounds, "DM85:0.5,vero:0.6,tip=2mm", "office"), HasSubstr("1.1"));
  EXPECT_EQ(refusal(sounds, "cryon", "office"), "");
}

TEST(ToolSound, APrintTheCatalogHasNotMeasuredIsPlayedAsTheDesignItIsPrintedAs) {
  const auto catalog = io::read_catalog(nibrig::test::assets_dir() / "default_catalog.json");
  const auto pla = unmeasured_print(catalog, "PLA-1mm");
  ASSERT_TRUE(pla.has_value());
  ASSERT_EQ(pla->mix.size(), 1u);
  EXPECT_EQ(pla->mix.front().material, "PLA");
  EXPECT_DOUBLE_EQ(pla->mix.front().fraction, 1.0);
  EXPECT_DOUBLE_EQ(pla->tip_diameter_m, 0.001);
  // The catalog's own prints and tools are what it measured; an id of no print is nothing.
  EXPECT_FALSE(unmeasured_print(catalog, "vero2").has_value());
  EXPECT_FALSE(unmeasured_print(catalog, "cryon").has_value());
  EXPECT_FALSE(unmeasured_print(catalog, "brand_new_nib").has_value());
  // So the simulated rig may mount it on any surface: nothing to refuse before the prediction.
  const ToolSounds sounds({});
  EXPECT_EQ(refusal(sounds, "PLA-1mm", "office"), "");
}

TEST(ToolSound, ACatalogToolIsItsMeasuredSpectrumThroughTheBundledStylus) {
  ToolSounds sounds({});
  const ToolSound cryon = sounds.sound("cryon", "office");
  const ToolSound stab = sounds.sound("stab", "note");
  const auto catalog = io::read_catalog(nibrig::test::assets_dir() / "default_catalog.json");
  EXPECT_EQ(cryon.spectrum.amplitude_m_s2,
            pairing_spectrum(catalog, "", "cryon", "office").amplitude_m_s2);
  EXPECT_EQ(cryon.name, "cryon on office");
  // The bundled stylus, meshed once: both tools run the same modes.
  const auto materials =
      mechanics::read_material_table(nibrig::test::assets_dir() / "materials.json");
  const auto stylus = mechanics::read_design(
      nibrig::test::assets_dir() / "designs" / "stylus_vero_tip2mm.json", materials);
  EXPECT_EQ(cryon.modes, stylus.name);
  EXPECT_EQ(static_cast<int>(cryon.modal.size()), stylus.modes);
  EXPECT_EQ(cryon.modal.omega, stab.modal.omega);
}

}  // namespace
}  // namespace nibrig::model::design
