// `nibrig export` as typed, its files handed to the real consumers a user hands them to: admesh
// checks each STL, PrusaSlicer reads the 3MF and slices it.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "model/mechanics/region_surface.hpp"
#include "model/mesh_io/stylus_3mf.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

// Every "name : number" admesh reports, by name (the first column where it prints two).
std::map<std::string, double> admesh_figures(const std::string& report) {
  std::map<std::string, double> out;
  const std::regex line(R"(([A-Za-z][A-Za-z0-9 ]*?)\s*:\s*(-?[0-9.]+))");
  for (auto it = std::sregex_iterator(report.begin(), report.end(), line); it != std::sregex_iterator(); ++it)
    out.emplace((*it)[1].str(), std::stod((*it)[2].str()));
  return out;
}

// PrusaSlicer's --info: one block of "key = value" per object, each headed "[<file name>]" (its
// log lines start with '[' too, with a time stamp).
std::vector<std::map<std::string, std::string>> prusa_info(const std::string& report, const std::string& file_name) {
  std::vector<std::map<std::string, std::string>> blocks;
  std::istringstream in(report);
  for (std::string l; std::getline(in, l);) {
    if (l == "[" + file_name + "]") blocks.emplace_back();
    const auto eq = l.find(" = ");
    if (eq != std::string::npos && !blocks.empty()) {
      std::string key = l.substr(0, eq), value = l.substr(eq + 3);
      while (!key.empty() && key.back() == ' ') key.pop_back();
      while (!value.empty() && value.front() == ' ') value.erase(0, 1);
      blocks.back()[key] = value;
    }
  }
  return blocks;
}

TEST(ExportCli, AMixedDesignsFilesAreCleanForAdmeshAndSliceInPrusaSlicer) {
  const auto out = nibrig::test::scratch_dir("cli_export");
  ::testing::internal::CaptureStdout();
  const int code = test::run_cli({"export", "DM85:0.62,vero:0.38,tip=2.7mm", "-o", (out / "stylus.3mf").string()});
  const std::string said = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << said;
  const auto regions = model::mesh_io::read_3mf_regions(out / "stylus.3mf");
  ASSERT_EQ(regions.size(), 2u);
  // Without a surface the sheet holds the print alone (its content: tests/ui/figures).
  EXPECT_TRUE(nibrig::test::is_png(out / "stylus-sheet.png"));

  for (const auto& region : regions) {
    const auto stl = out / ("stylus-" + region.surface.name + ".stl");
    const auto run = nibrig::test::run_program({"admesh", stl.string()}, out);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const auto figures = admesh_figures(run.output);
    for (const char* zero : {"Total disconnected facets", "Degenerate facets", "Edges fixed", "Facets removed",
                             "Facets added", "Facets reversed", "Backwards edges", "Normals fixed"}) {
      ASSERT_TRUE(figures.count(zero)) << zero << " missing from\n" << run.output;
      EXPECT_EQ(figures.at(zero), 0.0) << stl << ": " << zero;
    }
    EXPECT_EQ(figures.at("Number of parts"), 1.0) << stl;
    // admesh's volume from the STL's float millimetres against ours from the same surface in
    // double metres: float rounding, a part in 10⁵.
    const double ours_mm3 = model::mechanics::enclosed_volume(region.surface) * 1e9;
    EXPECT_NEAR(figures.at("Volume"), ours_mm3, 1e-5 * ours_mm3) << stl;
  }

  // PrusaSlicer takes each object as manifold and on its 200 × 200 mm bed, and slices without a
  // warning (--loglevel 2 prints its warnings and errors, nothing else).
  const auto info = nibrig::test::run_program({"prusa-slicer", "--loglevel", "2", "--info", (out / "stylus.3mf").string()}, out);
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const auto blocks = prusa_info(info.output, "stylus.3mf");
  ASSERT_EQ(blocks.size(), 2u) << info.output;
  for (const auto& b : blocks) {
    EXPECT_EQ(b.at("manifold"), "yes");
    EXPECT_GE(std::stod(b.at("min_z")), 0.0);
    for (const char* axis : {"x", "y"}) {
      EXPECT_GE(std::stod(b.at(std::string("min_") + axis)), 0.0) << axis;
      EXPECT_LE(std::stod(b.at(std::string("max_") + axis)), 200.0) << axis;
    }
  }
  const auto sliced = nibrig::test::run_program(
      {"prusa-slicer", "--loglevel", "2", "--export-gcode", (out / "stylus.3mf").string(), "-o", (out / "stylus.gcode").string()}, out);
  ASSERT_EQ(sliced.exit_code, 0) << sliced.output;
  EXPECT_EQ(sliced.output.find("warning"), std::string::npos) << sliced.output;
  EXPECT_EQ(sliced.output.find("error"), std::string::npos) << sliced.output;
  std::ifstream gcode(out / "stylus.gcode");
  const std::string text((std::istreambuf_iterator<char>(gcode)), std::istreambuf_iterator<char>());
  std::smatch used;
  ASSERT_TRUE(std::regex_search(text, used, std::regex(R"(; filament used \[cm3\] = ([0-9.]+))"))) << "no G-code summary";
  EXPECT_GT(std::stod(used[1].str()), 0.0);
}

TEST(ExportCli, ABadDesignOrFolderIsRefusedAndNothingIsWritten) {
  const auto out = nibrig::test::scratch_dir("cli_export_refused");
  std::ofstream(out / "a_file") << "not a folder";
  ::testing::internal::CaptureStderr();
  const int unknown = test::run_cli({"export", "wood,tip=2mm", "-o", (out / "wood.3mf").string()});
  const int too_wide = test::run_cli({"export", "vero,tip=12mm", "-o", (out / "wide.3mf").string()});
  const int in_a_file = test::run_cli({"export", "vero,tip=2mm", "-o", (out / "a_file" / "stylus.3mf").string()});
  // A place in a space is found from the prediction, which needs the surface.
  const int space_alone = test::run_cli({"export", "vero,tip=2mm", "--space", (out / "a_file").string(), "-o",
                                         (out / "placed.3mf").string()});
  const std::string errors = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(unknown, 0);
  EXPECT_NE(too_wide, 0);
  EXPECT_NE(in_a_file, 0);
  EXPECT_NE(space_alone, 0);
  EXPECT_NE(errors.find("--surface"), std::string::npos) << errors;
  EXPECT_NE(errors.find("wood"), std::string::npos) << errors;
  EXPECT_NE(errors.find("a_file"), std::string::npos) << errors;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(out), std::filesystem::directory_iterator()), 1) << errors;
}

}  // namespace
}  // namespace nibrig::ui::cli
