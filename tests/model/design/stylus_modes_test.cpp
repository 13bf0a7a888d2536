// The stylus's modes kept in the user cache: a miss solves the FEM and writes the modes, a hit
// reads back exactly what the FEM gives, and a file that does not read is solved again. A coarse
// copy of the bundled stylus (8 modes on a 6 mm mesh) keeps the solves to seconds.
#include "model/design/stylus_modes.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "model/mechanics/design_model.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

std::filesystem::path coarse_stylus(const std::filesystem::path& dir) {
  std::ifstream in(nibrig::test::assets_dir() / "designs" / "stylus_vero_tip2mm.json");
  nlohmann::json design = nlohmann::json::parse(in);
  design["mesh_size"] = 0.006;
  design["modes"] = 8;
  const auto file = dir / "coarse_stylus.json";
  std::ofstream(file) << design.dump();
  return file;
}

TEST(StylusModes, AMissSolvesAndWritesAndAHitReadsExactlyWhatTheFemGives) {
  const auto dir = nibrig::test::scratch_dir("stylus_modes_cache");
  std::filesystem::remove_all(dir / "cache");
  const auto design = coarse_stylus(dir);

  EXPECT_FALSE(std::filesystem::exists(stylus_modes_file(design, dir / "cache")));
  const auto miss = stylus_modes(design, dir / "cache");
  EXPECT_TRUE(miss.computed);
  // Where a face looks to know whether a click will solve the modes first.
  EXPECT_EQ(stylus_modes_file(design, dir / "cache"), miss.file);
  EXPECT_TRUE(miss.warnings.empty());
  EXPECT_TRUE(std::filesystem::exists(miss.file));
  const auto hit = stylus_modes(design, dir / "cache");
  EXPECT_FALSE(hit.computed);
  EXPECT_EQ(hit.file, miss.file);

  // The reference: the FEM run here, outside the cache. The file keeps every double's shortest
  // round-trip digits, so what is read is equal, not merely close.
  const auto materials = mechanics::read_material_table(nibrig::test::assets_dir() / "materials.json");
  const auto fem = mechanics::build_design_model(mechanics::read_design(design, materials), materials);
  ASSERT_EQ(hit.value.modal.size(), 8u);
  EXPECT_EQ(hit.value.design_name, "VeroClear stylus, 2 mm tip");
  EXPECT_EQ(hit.value.modal.omega, fem.modal.omega);
  EXPECT_EQ(hit.value.modal.zeta, fem.modal.zeta);
  EXPECT_EQ(hit.value.modal.input, fem.modal.input);
  EXPECT_EQ(hit.value.modal.output, fem.modal.output);
  EXPECT_EQ(miss.value.modal.omega, fem.modal.omega);

  // Another design is another key, another file.
  nlohmann::json six = nlohmann::json::parse(std::ifstream(design));
  six["modes"] = 6;
  std::ofstream(dir / "six_modes.json") << six.dump();
  EXPECT_NE(stylus_modes(dir / "six_modes.json", dir / "cache").file, miss.file);
}

TEST(StylusModes, AFileThatDoesNotReadIsSolvedAgainWithAWarningNamingIt) {
  const auto dir = nibrig::test::scratch_dir("stylus_modes_broken");
  std::filesystem::remove_all(dir / "cache");
  const auto design = coarse_stylus(dir);
  const auto first = stylus_modes(design, dir / "cache");
  std::ofstream(first.file) << R"({"format": "nibrig-stylus-modes", "version": 1, "design": "x",)";
  const auto again = stylus_modes(design, dir / "cache");
  EXPECT_TRUE(again.computed);
  ASSERT_EQ(again.warnings.size(), 1u);
  EXPECT_NE(again.warnings[0].find(first.file.string()), std::string::npos) << again.warnings[0];
  EXPECT_EQ(again.value.modal.omega, first.value.modal.omega);
  EXPECT_FALSE(stylus_modes(design, dir / "cache").computed);  // the file was written anew
}

}  // namespace
}  // namespace nibrig::model::design
