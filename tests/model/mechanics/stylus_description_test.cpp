#include "model/mechanics/stylus_description.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "model/io/format_error.hpp"
#include "model/mechanics/gmsh_session.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::mechanics {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

const MaterialTable& bundled_materials() {
  static const MaterialTable table = read_material_table(nibrig::test::assets_dir() / "materials.json");
  return table;
}

std::filesystem::path write_design(const std::string& name, const std::string& body) {
  const auto file = nibrig::test::scratch_dir("design") / name;
  std::ofstream(file) << R"({"format": "nibrig-design", "version": 1, )" << body << "}";
  return file;
}

TEST(Design, BundledDesignsReadAndMesh) {
  for (const auto& entry : std::filesystem::directory_iterator(nibrig::test::assets_dir() / "designs")) {
    const Design design = read_design(entry.path(), bundled_materials());
    EXPECT_FALSE(design.name.empty()) << entry.path();
    EXPECT_NEAR(design.tip.direction.norm(), 1.0, 1e-12);
    EXPECT_NEAR(design.sensor.direction.norm(), 1.0, 1e-12);
  }
  const Design bar =
      read_design(nibrig::test::assets_dir() / "designs" / "paper_bar.json", bundled_materials());
  const auto& shape = std::get<BarGeometry>(bar.shape);
  EXPECT_DOUBLE_EQ(shape.free_length(), 0.180);  // 210 mm clamped over 30 mm
  const TetMesh mesh = mesh_design(bar);
  EXPECT_FALSE(mesh.node_sets.at("clamp").empty());
}

TEST(Design, DefaultsPutTheTipAtTheApexAndTheSensorOnTheBody) {
  const Design d =
      read_design(write_design("stylus.json", R"("shape": {"kind": "stylus", "tip_diameter": 0.001},
      "materials": {"body": "VeroClear"})"),
                  bundled_materials());
  const auto& s = std::get<StylusGeometry>(d.shape);
  EXPECT_TRUE(d.tip.point.isApprox(s.apex()));
  EXPECT_DOUBLE_EQ(d.sensor.point.y(), s.body_diameter / 2);  // on the surface
  EXPECT_GT(d.sensor.point.x(), s.grip_length);               // outside the holder
  EXPECT_FALSE(d.damping.has_value());
}

TEST(Design, ExplicitProbesAreNormalised) {
  const Design d =
      read_design(write_design("probes.json", R"("shape": {"kind": "bar", "cutout": false},
      "materials": {"body": "steel"}, "tip": {"point": [0.17, 0, 0], "direction": [0, 0, -2]},
      "sensor": {"point": [0.1, 0, 0.001], "axis": [0, 3, 4]}, "damping": {"rayleigh_stiffness": 1e-6})"),
                  bundled_materials());
  EXPECT_TRUE(d.tip.direction.isApprox(Eigen::Vector3d(0, 0, -1)));
  EXPECT_TRUE(d.sensor.direction.isApprox(Eigen::Vector3d(0, 0.6, 0.8)));
  ASSERT_TRUE(d.damping.has_value());
  EXPECT_DOUBLE_EQ(d.damping->stiffness, 1e-6);
}

TEST(Design, BadDesignsNameTheFieldAndWhatWasExpected) {
  const auto& materials = bundled_materials();
  auto fails_with = [&](const std::string& name, const std::string& body, const std::string& field,
                        const std::string& expected) {
    EXPECT_THAT([&] { read_design(write_design(name, body), materials); },
                ::testing::ThrowsMessage<io::FormatError>(
                    AllOf(HasSubstr(name), HasSubstr(field), HasSubstr(expected))))
        << name;
  };
  fails_with("kind.json", R"("shape": {"kind": "pencil"}, "materials": {"body": "steel"})",
             "shape.kind", "expected \"bar\", \"stylus\" or \"file\"");
  fails_with("typo.json",
             R"("shape": {"kind": "stylus", "tip_diamter": 0.001}, "materials": {"body": "steel"})",
             "shape.tip_diamter", "unknown field");
  fails_with("material.json", R"("shape": {"kind": "bar"}, "materials": {"body": "kryptonite"})",
             "materials.body", "unknown material 'kryptonite'");
  fails_with("negative.json",
             R"("shape": {"kind": "bar", "thickness": -0.002}, "materials": {"body": "steel"})",
             "shape", "thickness");
  fails_with(
      "direction.json",
      R"("shape": {"kind": "bar"}, "materials": {"body": "steel"}, "tip": {"direction": [0, 0, 0]})",
      "tip.direction", "non-zero");
  fails_with("file.json",
             R"("shape": {"kind": "file", "path": "nib.stl"}, "materials": {"body": "steel"})",
             "tip", "must say where its tip and sensor are");
}

// Sizes no stylus has (a body_length of 1e3 m ends inside Gmsh, a mesh_size of 1e-300 never
// finishes) are refused while the file is read, naming the file and the field, before Gmsh is
// reached.
TEST(Design, SizesNoStylusCanHaveAreRefusedWhileReading) {
  const auto& materials = bundled_materials();
  struct Case {
    const char* name;
    const char* shape;
    const char* mesh_size;  // nullptr: the default
    const char* field;
    const char* expected;
  };
  const Case cases[] = {
      {"km.json", R"("kind": "stylus", "body_length": 1e3)", nullptr, "shape", "body length"},
      // Past 1e15 every JSON reader refuses a number before the shape's own bound sees it.
      {"huge.json", R"("kind": "stylus", "body_length": 1e300)", nullptr, "shape.body_length", "1e+15"},
      {"five_m.json", R"("kind": "stylus", "body_length": 5)", nullptr, "shape", "body length"},
      {"thin.json", R"("kind": "stylus", "tip_diameter": 1e-300)", nullptr, "shape", "tip diameter"},
      {"wide_bar.json", R"("kind": "bar", "width": 2)", nullptr, "shape", "width"},
      {"fine.json", R"("kind": "stylus")", "1e-300", "mesh_size", "between"},
      {"denormal.json", R"("kind": "stylus")", "1e-320", "mesh_size", "between"},
      {"coarse.json", R"("kind": "stylus")", "1e3", "mesh_size", "between"},
      {"too_many.json", R"("kind": "stylus")", "0.0001", "mesh_size", "elements"},
  };
  for (const Case& c : cases) {
    std::string body = std::string(R"("shape": {)") + c.shape + R"(}, "materials": {"body": "steel"})";
    if (c.mesh_size != nullptr) body += std::string(R"(, "mesh_size": )") + c.mesh_size;
    EXPECT_THAT([&] { read_design(write_design(c.name, body), materials); },
                ::testing::ThrowsMessage<io::FormatError>(
                    AllOf(HasSubstr(c.name), HasSubstr(c.field), HasSubstr(c.expected))))
        << c.name;
  }
}

// Whatever Gmsh throws becomes our error naming what was being done: Gmsh 4.8 throws bare strings.
TEST(Design, WhatGmshThrowsBecomesAnErrorNamingTheStep) {
  EXPECT_THAT([] { guard_gmsh("meshing the stylus", []() -> int { throw std::string("boom"); }); },
              ::testing::ThrowsMessage<std::runtime_error>(
                  ::testing::StrEq("meshing the stylus: Gmsh: boom")));
  EXPECT_THAT([] { guard_gmsh("reading", []() -> int { throw 42; }); },
              ::testing::ThrowsMessage<std::runtime_error>(HasSubstr("reading: Gmsh failed")));
  EXPECT_EQ(guard_gmsh("adding", [] { return 7; }), 7);
}

TEST(Design, AnInlineBarMeshesAtItsThicknessButNoFinerThanAHundredthOfItsLength) {
  BarGeometry bar;  // the paper's bar: 210 mm, 30 mm clamped, 2 mm thick
  // Hand computation: free length 180 mm / 100 = 1.8 mm < 2 mm thick, so the thickness rules.
  EXPECT_DOUBLE_EQ(bar_mesh_size(bar), 0.002);
  bar.thickness = 0.0005;  // 0.5 mm < 1.8 mm: the hundredth of the free length rules
  EXPECT_DOUBLE_EQ(bar_mesh_size(bar), 0.0018);
  bar.length = 0.090;  // free 60 mm → 0.6 mm, now above the 0.5 mm thickness
  EXPECT_DOUBLE_EQ(bar_mesh_size(bar), 0.0006);

  const Design d = bar_design(bar, "VeroClear-Piovarci2018");
  EXPECT_EQ(d.name, "bar 90.00 mm");
  EXPECT_DOUBLE_EQ(d.mesh_size, bar_mesh_size(bar));
  EXPECT_EQ(d.modes, 12);
  EXPECT_EQ(d.region_materials.at("body"), "VeroClear-Piovarci2018");
  // The probes are the bar's stated defaults: tip at the middle of the free end, sensor 20 mm in.
  EXPECT_TRUE(d.tip.point.isApprox(default_tip(bar).point));
  EXPECT_TRUE(d.sensor.point.isApprox(default_sensor(bar).point));
  ASSERT_TRUE(std::holds_alternative<BarGeometry>(d.shape));
  EXPECT_DOUBLE_EQ(std::get<BarGeometry>(d.shape).thickness, 0.0005);

  bar.thickness = 0;  // impossible shapes are refused before anything is meshed
  EXPECT_THROW(bar_design(bar, "VeroClear-Piovarci2018"), std::invalid_argument);
}

TEST(Design, MeshWithoutClampIsRefused) {
  // A mesh file whose clamp box holds no node: the design would float freely.
  const auto dir = nibrig::test::scratch_dir("design_clamp");
  {
    std::ofstream stl(dir / "cube.stl");
    const double v[8][3] = {{0, 0, 0},  {10, 0, 0},  {10, 10, 0},  {0, 10, 0},
                            {0, 0, 10}, {10, 0, 10}, {10, 10, 10}, {0, 10, 10}};
    const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                          {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    stl << "solid c\n";
    for (const auto& t : f) {
      stl << "facet normal 0 0 0\nouter loop\n";
      for (int k : t) stl << "vertex " << v[k][0] << " " << v[k][1] << " " << v[k][2] << "\n";
      stl << "endloop\nendfacet\n";
    }
    stl << "endsolid c\n";
  }
  std::ofstream(dir / "floating.json") << R"({"format": "nibrig-design", "version": 1,
    "shape": {"kind": "file", "path": "cube.stl", "clamp_box": {"min": [1, 1, 1], "max": [2, 2, 2]}},
    "materials": {"body": "steel"}, "tip": {"point": [0.005, 0.005, 0.01]}, "sensor": {"point": [0.005, 0.005, 0]},
    "mesh_size": 0.004})";
  const Design d = read_design(dir / "floating.json", bundled_materials());
  EXPECT_THAT([&] { mesh_design(d); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("no clamped region")));
}

}  // namespace
}  // namespace nibrig::model::mechanics
