// The 3MF and STL writers on a surface whose every number is known: a unit cube in two regions
// (two 1 × 1 × 0.5 mm halves sharing the face z = 0.5 mm).
#include "model/io/stylus_3mf.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>

#include "model/io/stl_writer.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

// An axis-aligned box from lo to hi (metres), its 12 triangles wound outward.
SurfaceMesh box(const std::string& name, std::array<double, 3> lo, std::array<double, 3> hi) {
  SurfaceMesh s;
  s.name = name;
  for (int i = 0; i < 8; ++i)
    s.vertices.push_back({(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]});
  s.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return s;
}

float f32_at(const std::string& bytes, std::size_t at) {
  float f = 0;
  std::memcpy(&f, bytes.data() + at, 4);
  return f;
}

TEST(StlWriter, BinaryStlHoldsEachTriangleInMillimetresWithItsOutwardNormal) {
  const auto s = box("body", {0, 0, 0}, {1e-3, 2e-3, 3e-3});
  const std::string bytes = binary_stl(s);
  ASSERT_EQ(bytes.size(), 84u + 50u * 12u);
  EXPECT_NE(bytes.rfind("solid", 0), 0u);  // an ASCII reader's cue, never at the start
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  EXPECT_EQ(count, 12u);
  // The first triangle (0, 2, 1) lies in z = 0 and faces -z; its corners in mm (float: exact here).
  EXPECT_EQ(f32_at(bytes, 84 + 8), -1.0f);
  EXPECT_EQ(f32_at(bytes, 84 + 12 + 12 + 4), 2.0f);  // vertex 2's y
  const SurfaceMesh broken{"bad", {{0, 0, 0}}, {{0, 1, 2}}};
  EXPECT_THROW(binary_stl(broken), std::invalid_argument);
}

TEST(Stylus3mf, ARegionPerObjectReadsBackWithItsMaterialInMillimetresToFloatPrecision) {
  const auto dir = nibrig::test::scratch_dir("stylus_3mf");
  ThreeMfPart part;
  part.name = "two halves";
  part.regions = {{box("lower", {0, 0, 0}, {1e-3, 1e-3, 0.5e-3}), "VeroClear", {200, 200, 220}},
                  {box("upper", {0, 0, 0.5e-3}, {1e-3, 1e-3, 1e-3}), "DM85 62 % + vero 38 %", {90, 90, 110}}};
  part.metadata = {{"Title", "two halves"}};
  part.placement_m = {0.1, 0.1, 0};
  const auto file = dir / "halves.3mf";
  write_3mf(file, part);
  const auto back = read_3mf_regions(file);
  ASSERT_EQ(back.size(), 2u);
  for (std::size_t r = 0; r < 2; ++r) {
    EXPECT_EQ(back[r].surface.name, part.regions[r].surface.name);
    EXPECT_EQ(back[r].material, part.regions[r].material);
    ASSERT_EQ(back[r].surface.triangles, part.regions[r].surface.triangles);
    ASSERT_EQ(back[r].surface.vertices.size(), 8u);
    // Coordinates go through float millimetres: 1 mm is exact, 0.5 mm too; the object keeps its
    // own coordinates (the placement is the build item's).
    for (std::size_t v = 0; v < 8; ++v)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(back[r].surface.vertices[v][static_cast<std::size_t>(k)],
                    part.regions[r].surface.vertices[v][static_cast<std::size_t>(k)], 1e-12);
  }
  // A part without regions is refused before anything is written.
  EXPECT_THROW(write_3mf(dir / "empty.3mf", ThreeMfPart{}), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir / "empty.3mf"));
}

TEST(Stylus3mf, AFileThatIsNotA3mfIsRefusedNamingIt) {
  const auto dir = nibrig::test::scratch_dir("stylus_3mf_bad");
  std::ofstream(dir / "not.3mf") << "plain text";
  try {
    read_3mf_regions(dir / "not.3mf");
    FAIL() << "read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not.3mf"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::model::io
