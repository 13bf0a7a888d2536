// The lab's own material table: saved under the user store, never over the bundled file; a bundled
// name refused; found by name after the table's own; an unknown name's error says where it looked.
#include "model/mechanics/lab_materials.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "model/io/bundled_assets.hpp"
#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::mechanics {
namespace {

using ::testing::HasSubstr;

std::string lab_file_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Material lab_pla(const std::string& name) {
  Material m;
  m.name = name;
  m.youngs_modulus = 2.1e9;  // any valid constants: the table is under test, not the numbers
  m.poisson_ratio = 0.36;
  m.density = 1240;
  m.damping = RayleighDamping{0.0, 3e-4};
  m.basis = "fitted";
  m.source = "test";
  return m;
}

TEST(LabMaterials, SavedInTheUserStoreBesideNeverOverTheBundledTable) {
  const auto store = nibrig::test::scratch_dir("lab_materials_saved");
  const nibrig::test::ScopedEnvironment lab("NIBRIG_MATERIALS", store.string());
  const auto bundled_file = io::default_materials();
  const std::string bundled_before = lab_file_text(bundled_file);
  const MaterialTable bundled = read_material_file(bundled_file);
  const auto file = save_lab_material(lab_pla("my-pla"), {{"recording", "r.csv"}}, bundled, false);
  EXPECT_EQ(file, store / "my-pla.json");
  EXPECT_EQ(lab_file_text(bundled_file), bundled_before);

  const MaterialTable table = read_material_table(bundled_file);
  ASSERT_EQ(table.materials().size(), bundled.materials().size() + 1);
  EXPECT_EQ(table.materials().back().name, "my-pla");  // after the bundled ones
  EXPECT_EQ(table.find("My-PLA").basis, "fitted");
  EXPECT_EQ(table.find("PLA").youngs_modulus, bundled.find("PLA").youngs_modulus);
  // The file says what it was fitted from.
  const auto saved = nlohmann::json::parse(lab_file_text(file));
  EXPECT_EQ(saved["calibration"]["recording"], "r.csv");

  // Saved again under that name only on purpose.
  EXPECT_THROW(save_lab_material(lab_pla("my-pla"), {}, bundled, false), std::invalid_argument);
  EXPECT_NO_THROW(save_lab_material(lab_pla("my-pla"), {}, bundled, true));
}

TEST(LabMaterials, ABundledNameIsRefusedAndADistinctOneTaken) {
  const nibrig::test::ScopedEnvironment lab(
      "NIBRIG_MATERIALS", nibrig::test::scratch_dir("lab_materials_bundled_name").string());
  const MaterialTable bundled = read_material_file(io::default_materials());
  try {
    save_lab_material(lab_pla("pla"), {}, bundled, true);  // even with replace: never the bundled
    FAIL() << "a bundled name was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("'pla' is a bundled material's"));
    EXPECT_THAT(e.what(), HasSubstr("distinct name"));
  }
  EXPECT_TRUE(nibrig::test::files_in(lab_materials_folder()).empty());
  EXPECT_NO_THROW(save_lab_material(lab_pla("pla-lab"), {}, bundled, false));
}

TEST(LabMaterials, AnUnknownNameSaysWhereItLooked) {
  const auto store = nibrig::test::scratch_dir("lab_materials_unknown");
  const nibrig::test::ScopedEnvironment lab("NIBRIG_MATERIALS", store.string());
  const MaterialTable table = read_material_table(io::default_materials());
  try {
    table.find("no-such-resin");
    FAIL() << "an unknown material was found";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown material 'no-such-resin'"));
    EXPECT_THAT(e.what(), HasSubstr(io::default_materials().string()));
    EXPECT_THAT(e.what(), HasSubstr("the lab's materials in " + store.string()));
  }
}

TEST(LabMaterials, ATableGivenByNameWinsOverALabMaterialOfTheSameName) {
  const nibrig::test::ScopedEnvironment lab(
      "NIBRIG_MATERIALS", nibrig::test::scratch_dir("lab_materials_shadow").string());
  const MaterialTable bundled = read_material_file(io::default_materials());
  save_lab_material(lab_pla("shop-resin"), {}, bundled, false);
  const auto own = nibrig::test::scratch_dir("lab_materials_own_table") / "own.json";
  std::ofstream(own) << R"({"format": "nibrig-materials", "version": 1, "materials": [
    {"name": "shop-resin", "youngs_modulus": 1.5e9, "poisson_ratio": 0.4, "density": 1100,
     "source": "the lab's own table"}]})";
  const MaterialTable table = read_material_table(own);
  ASSERT_EQ(table.materials().size(), 1u);  // the lab's of that name is left out
  EXPECT_EQ(table.find("shop-resin").youngs_modulus, 1.5e9);
}

TEST(LabMaterials, AFileRenamedByHandOrHoldingTwoIsRefusedNamingIt) {
  const auto store = nibrig::test::scratch_dir("lab_materials_bad_file");
  const nibrig::test::ScopedEnvironment lab("NIBRIG_MATERIALS", store.string());
  std::ofstream(store / "other.json")
      << R"({"format": "nibrig-materials", "version": 1, "materials": [
    {"name": "shop-resin", "youngs_modulus": 1.5e9, "poisson_ratio": 0.4, "density": 1100,
     "source": "s"}]})";
  try {
    read_lab_materials(store);
    FAIL() << "a renamed file was read";
  } catch (const io::FormatError& e) {
    EXPECT_THAT(e.what(), HasSubstr("other.json"));
    EXPECT_THAT(e.what(), HasSubstr("shop-resin.json"));
  }
}

TEST(LabMaterials, ABrokenFileIsLeftOutAndNamedWhenItsMaterialIsAskedFor) {
  const auto store = nibrig::test::scratch_dir("lab_materials_broken_file");
  const nibrig::test::ScopedEnvironment lab("NIBRIG_MATERIALS", store.string());
  const MaterialTable bundled = read_material_file(io::default_materials());
  save_lab_material(lab_pla("shop-pla"),
                    {{"printed_as", "PLA"},
                     {"youngs_modulus_sd", 1e7},
                     {"rayleigh_stiffness_sd", 1e-6},
                     {"modulus_damping_correlation", -0.2}},
                    bundled, false);
  std::ofstream(store / "half-written.json")
      << R"({"format": "nibrig-materials", "version": 1, "mater)";
  // Every other material is found, the lab's own with what it was printed as.
  const MaterialTable table = read_material_table(io::default_materials());
  EXPECT_EQ(table.find("shop-pla").printed_as, "PLA");
  // With how sure its ring-down is, which predictions carry.
  EXPECT_EQ(table.find("shop-pla").youngs_modulus_sd, 1e7);
  EXPECT_EQ(table.find("shop-pla").rayleigh_stiffness_sd, 1e-6);
  EXPECT_EQ(table.find("shop-pla").modulus_damping_correlation, -0.2);
  EXPECT_FALSE(table.find("PETG").youngs_modulus_sd.has_value());
  EXPECT_EQ(table.find("PETG").printed_as, "");
  // The broken one is named, with why, where a material is looked for in vain.
  try {
    table.find("half-written");
    FAIL() << "a broken file's material was found";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("skipped " + (store / "half-written.json").string() + " line 1"));
  }
  // The strict reading, for a face that lists the lab's materials, still refuses it.
  EXPECT_THROW(read_lab_materials(store), io::FormatError);
}

TEST(LabMaterials, ACachedResultsKeyChangesWithTheLabsFilesAndOnlyWithThem) {
  const auto store = nibrig::test::scratch_dir("lab_materials_cache_key");
  const nibrig::test::ScopedEnvironment lab("NIBRIG_MATERIALS", store.string());
  const auto key = [&] {
    io::CacheKey k;
    add_lab_materials(k, store);
    return k.hex();
  };
  const std::string none = key();
  const MaterialTable bundled = read_material_file(io::default_materials());
  save_lab_material(lab_pla("shop-pla"), {}, bundled, false);
  const std::string one = key();
  EXPECT_NE(one, none);
  EXPECT_EQ(key(), one);  // nothing changed: the same key
  Material stiffer = lab_pla("shop-pla");
  stiffer.youngs_modulus *= 1.1;
  save_lab_material(stiffer, {}, bundled, true);  // recalibrated
  EXPECT_NE(key(), one);
  std::filesystem::remove(store / "shop-pla.json");
  EXPECT_EQ(key(), none);
}

}  // namespace
}  // namespace nibrig::model::mechanics
