// `nibrig rig parts` as typed, its files handed to the consumers a builder hands them to: admesh
// checks each STL, PrusaSlicer takes each 3MF with its settings and slices it.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

namespace fs = std::filesystem;

// Every "name : number" admesh reports, by name (the first column where it prints two).
std::map<std::string, double> rig_parts_admesh(const std::string& report) {
  std::map<std::string, double> out;
  const std::regex line(R"(([A-Za-z][A-Za-z0-9 ]*?)\s*:\s*(-?[0-9.]+))");
  for (auto it = std::sregex_iterator(report.begin(), report.end(), line);
       it != std::sregex_iterator(); ++it)
    out.emplace((*it)[1].str(), std::stod((*it)[2].str()));
  return out;
}

// A "; key = value" line of PrusaSlicer's G-code (its settings and its summary, at the end).
std::string gcode_value(const std::string& gcode, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(
          gcode, m,
          std::regex("\n; " + std::regex_replace(key, std::regex(R"([\[\]])"), R"(\$&)") +
                     " = ([^\n]*)")))
    return {};
  return m[1].str();
}

TEST(RigPartsCli, EveryPartIsCleanForAdmeshAndSlicesWithItsSettings) {
  const auto out = nibrig::test::scratch_dir("cli_rig_parts");
  std::ofstream(out / "notes.txt") << "the builder's own notes";
  ::testing::internal::CaptureStdout();
  const int code = test::run_cli({"rig", "parts", "-o", out.string()});
  const std::string said = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << said;
  std::ifstream notes(out / "notes.txt");
  std::string kept;
  std::getline(notes, kept);
  EXPECT_EQ(kept, "the builder's own notes");  // an existing folder keeps what else it holds

  const auto recipe = test::read_json(out / "rig_parts.json");
  ASSERT_EQ(recipe["parts"].size(), 5u);
  for (const auto& part : recipe["parts"]) {
    const std::string name = part["name"];
    SCOPED_TRACE(name);
    EXPECT_NE(said.find("wrote " + (out / (name + ".3mf")).string()), std::string::npos) << said;
    const double volume = part["volume_mm3"];

    const auto checked =
        nibrig::test::run_program({"admesh", (out / (name + ".stl")).string()}, out);
    ASSERT_EQ(checked.exit_code, 0) << checked.output;
    const auto figures = rig_parts_admesh(checked.output);
    for (const char* zero :
         {"Total disconnected facets", "Degenerate facets", "Edges fixed", "Facets removed",
          "Facets added", "Facets reversed", "Backwards edges", "Normals fixed"}) {
      ASSERT_TRUE(figures.count(zero)) << zero << " missing from\n" << checked.output;
      EXPECT_EQ(figures.at(zero), 0.0) << zero;
    }
    EXPECT_EQ(figures.at("Number of parts"), 1.0);
    // admesh sums its volume in single precision over up to 10⁵ facets: 2·10⁻⁴ off on the bridge's
    // 71 cm³ (the same STL's floats summed in double agree with ours to 10⁻⁸).
    EXPECT_NEAR(figures.at("Volume"), volume, 1e-3 * volume);

    // PrusaSlicer: one manifold object on the 200 × 200 mm bed, then sliced with the part's own
    // settings, which must reach the G-code.
    const auto three_mf = (out / (name + ".3mf")).string();
    const auto info =
        nibrig::test::run_program({"prusa-slicer", "--loglevel", "2", "--info", three_mf}, out);
    ASSERT_EQ(info.exit_code, 0) << info.output;
    EXPECT_NE(info.output.find("manifold = yes"), std::string::npos) << info.output;
    const auto gcode_file = out / (name + ".gcode");
    const auto sliced = nibrig::test::run_program(
        {"prusa-slicer", "--loglevel", "2", "--load", (out / (name + ".ini")).string(),
         "--export-gcode", three_mf, "-o", gcode_file.string()},
        out);
    ASSERT_EQ(sliced.exit_code, 0) << sliced.output;
    EXPECT_EQ(sliced.output.find("warning"), std::string::npos) << sliced.output;
    EXPECT_EQ(sliced.output.find("error"), std::string::npos) << sliced.output;
    std::ifstream in(gcode_file);
    const std::string gcode((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(gcode_value(gcode, "perimeters"),
              std::to_string(part["settings"]["perimeters"].get<int>()));
    EXPECT_EQ(gcode_value(gcode, "fill_density"),
              std::to_string(part["settings"]["fill_percent"].get<int>()) + "%");
    EXPECT_EQ(gcode_value(gcode, "filament_type"), part["material"].get<std::string>());
    const std::string used = gcode_value(gcode, "filament used [cm3]");
    ASSERT_FALSE(used.empty()) << "no G-code summary";
    const double used_mm3 = std::stod(used) * 1e3;
    if (part["settings"]["fill_percent"] == 100) {
      // Solid: the plastic laid is the part's volume, less the gaps between round extrusions and
      // plus the first layer's squash: within 10 % (the bracket measured 3 % over).
      EXPECT_NEAR(used_mm3, volume, 0.1 * volume);
    } else {
      // Half full inside 1.8 mm walls: between half the volume and all of it.
      EXPECT_GT(used_mm3, 0.5 * volume);
      EXPECT_LT(used_mm3, volume);
    }
  }
}

TEST(RigPartsCli, AFileInPlaceOfTheFolderIsRefusedNamingIt) {
  const auto out = nibrig::test::scratch_dir("cli_rig_parts_refused");
  std::ofstream(out / "a_file") << "not a folder";
  ::testing::internal::CaptureStderr();
  const int code = test::run_cli({"rig", "parts", "-o", (out / "a_file").string()});
  const int no_folder = test::run_cli({"rig", "parts"});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, 1);
  EXPECT_EQ(no_folder, 2);  // a usage error: -o is required
  EXPECT_NE(err.find("a_file"), std::string::npos) << err;
  EXPECT_EQ(nibrig::test::files_in(out).size(), 1u) << err;
}

}  // namespace
}  // namespace nibrig::ui::cli
