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
  Material m{"m", 1e9, 0.5, 1000, std::nullopt, "", "", "", std::nullopt, std::nullopt, 0.0};
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

// A lab's materials are in the bundled table, each marked with what its numbers stand on until a
// print calibrates it.
TEST(MaterialTable, TheLabsMaterialsSayTheyAreDatasheetValues) {
  const MaterialTable table = read_material_table(nibrig::test::assets_dir() / "materials.json");
  for (const char* name : {"PLA", "PETG", "TPU-95A", "resin-standard", "resin-flexible"}) {
    const Material& m = table.find(name);
    EXPECT_TRUE(m.basis == "datasheet" || m.basis == "estimate") << name << ": " << m.basis;
    EXPECT_THAT(m.source, HasSubstr("data sheet")) << name << " names its datasheet";
    EXPECT_EQ(describe_basis(m).find("not calibrated") != std::string::npos, true) << name;
  }
  EXPECT_EQ(table.find("VeroClear-Piovarci2018").basis, "fitted");
  for (const auto& m : table.materials()) EXPECT_TRUE(is_material_basis(m.basis)) << m.name << " states no basis";
}

TEST(MaterialTable, ABasisIsOptionalButOnlyOneOfThree) {
  const auto plain = write_table("no_basis.json", R"([{"name": "x", "youngs_modulus": 1e9, "poisson_ratio": 0.3,
                                                     "density": 1000, "source": "s"}])");
  EXPECT_EQ(describe_basis(read_material_table(plain).find("x")), "basis not stated");
  const auto bad = write_table("bad_basis.json", R"([{"name": "x", "youngs_modulus": 1e9, "poisson_ratio": 0.3,
                                                   "density": 1000, "basis": "guessed", "source": "s"}])");
  try {
    read_material_table(bad);
    ADD_FAILURE() << "a basis of 'guessed' was read";
  } catch (const io::FormatError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("bad_basis.json"), HasSubstr("materials[0]"), HasSubstr("guessed")));
  }
}

}  // namespace
}  // namespace nibrig::model::mechanics
