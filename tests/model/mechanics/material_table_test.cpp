#include "model/mechanics/material_table.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::mechanics {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::filesystem::path write_table(const std::string& name, const std::string& materials_json) {
  const auto file = nibrig::test::scratch_dir("material_table") / name;
  std::ofstream(file) << R"({"format": "nibrig-materials", "version": 1, "materials": )"
                      << materials_json << "}";
  return file;
}

TEST(MaterialTable, BundledTableHoldsThePapersVeroClearFit) {
  const MaterialTable table = read_material_table(nibrig::test::assets_dir() / "materials.json");
  const Material& vero = table.find("veroclear-piovarci2018");  // names are case-insensitive
  // Published values (Sec. 5.1): E = 0.45 GPa, Rayleigh stiffness term 1.25e-3, no mass term.
  EXPECT_DOUBLE_EQ(vero.youngs_modulus, 0.45e9);
  ASSERT_TRUE(vero.damping.has_value());
  EXPECT_DOUBLE_EQ(vero.damping->stiffness, 1.25e-3);
  EXPECT_DOUBLE_EQ(vero.damping->mass, 0.0);
  EXPECT_THAT(vero.source, HasSubstr("SIGGRAPH 2018"));
  for (const char* name : {"VeroClear", "DM85", "DM95", "steel", "graphite-lead"})
    EXPECT_FALSE(table.find(name).source.empty()) << name;
}

TEST(MaterialTable, UnknownNameListsTheKnownOnes) {
  const MaterialTable table = read_material_table(nibrig::test::assets_dir() / "materials.json");
  EXPECT_THAT([&] { table.find("unobtainium"); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  AllOf(HasSubstr("unknown material 'unobtainium'"), HasSubstr("VeroClear"))));
}

TEST(MaterialTable, NegativeModulusNamesFileAndField) {
  const auto file = write_table(
      "negative.json",
      R"([{"name": "bad", "youngs_modulus": -1e9, "poisson_ratio": 0.3, "density": 1000, "source": "x"}])");
  EXPECT_THAT([&] { read_material_table(file); },
              ::testing::ThrowsMessage<io::FormatError>(
                  AllOf(HasSubstr("negative.json"), HasSubstr("materials[0]"),
                        HasSubstr("Young's modulus must be positive"))));
}

TEST(MaterialTable, RejectsImpossiblePoissonRatioDensityAndDamping) {
  Material m{"m", 1e9, 0.5, 1000, std::nullopt, ""};
  EXPECT_THAT([&] { validate(m); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("Poisson ratio")));
  m.poisson_ratio = 0.3;
  m.density = 0;
  EXPECT_THAT([&] { validate(m); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("density")));
  m.density = 1000;
  m.damping = RayleighDamping{0.0, -1e-3};
  EXPECT_THAT([&] { validate(m); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("stiffness")));
}

TEST(MaterialTable, MissingFieldAndDuplicateNames) {
  const auto missing = write_table(
      "missing.json", R"([{"name": "m", "poisson_ratio": 0.3, "density": 1000, "source": "x"}])");
  EXPECT_THAT([&] { read_material_table(missing); },
              ::testing::ThrowsMessage<io::FormatError>(HasSubstr("youngs_modulus")));
  const auto twice = write_table("twice.json", R"([
    {"name": "m", "youngs_modulus": 1e9, "poisson_ratio": 0.3, "density": 1000, "source": "x"},
    {"name": "M", "youngs_modulus": 2e9, "poisson_ratio": 0.3, "density": 1000, "source": "y"}])");
  EXPECT_THAT([&] { read_material_table(twice); },
              ::testing::ThrowsMessage<io::FormatError>(HasSubstr("defined twice")));
}

}  // namespace
}  // namespace nibrig::model::mechanics
