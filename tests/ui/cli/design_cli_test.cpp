// End-to-end test of `nibrig design` on the bundled catalog, in a space made for the test: the
// 2-D space of the paper's descriptors (μ, log10 of the weighted mean vibration), with the
// coordinates of a handful of measured tools equal to their standardised descriptors and a
// small deterministic scatter, so that the descriptor map is known and the search's answer can be
// reasoned about.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "model/design/design_point.hpp"
#include "model/io/catalog_file.hpp"
#include "model/mechanics/region_surface.hpp"
#include "model/mesh_io/stylus_3mf.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "model/space/descriptor_map.hpp"
#include "model/space/space_file.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using nibrig::test::is_png;
using nibrig::test::read_json;
using test::run_cli;

namespace space = model::space;

std::filesystem::path write_test_space(const std::filesystem::path& folder) {
  const auto catalog_file = nibrig::test::assets_dir() / "default_catalog.json";
  const auto catalog = model::io::read_catalog(catalog_file);
  space::SpaceFile s;
  s.stimuli = {"cryon/office", "stab/office", "vero1/office", "vero4/office",
               "DM854/office", "vero1/glass", "DM851/glass",  "vero4/glass"};
  const auto table = space::descriptors_for_stimuli(catalog, catalog_file, s.stimuli, 2);
  s.descriptor_names = table.names;
  s.descriptors = table.values;
  const Eigen::Index n = table.values.rows();
  s.coordinates.resize(2, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double wobble = 0.05 * ((i % 3) - 1.0);  // leaves the map a residual to estimate
    s.coordinates(0, i) = 5 * table.values(i, 0) + wobble;
    s.coordinates(1, i) = table.values(i, 1) - wobble;
  }
  s.model.scale = 1.0;
  s.judgments = "none: a space made for the test";
  s.descriptor_map = space::fit_descriptor_map(s.coordinates, s.descriptors, s.descriptor_names);
  const auto file = folder / "space.json";
  space::write_space_file(file, s);
  return file;
}

// The predicted row of `space embed`'s CSV: its coordinates' standard deviations.
std::vector<double> predicted_sds(const std::filesystem::path& csv_file) {
  std::ifstream in(csv_file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("\"pred:", 0) != 0) continue;
    std::stringstream row(line.substr(line.rfind('"') + 2));
    std::vector<double> cells;
    for (std::string cell; std::getline(row, cell, ',');)
      if (cell != "no") cells.push_back(std::stod(cell));
    return {cells.at(1), cells.at(3)};  // axis1, axis1_sd, axis2, axis2_sd
  }
  ADD_FAILURE() << "no predicted row in " << csv_file;
  return {0, 0};
}

// predicted.json carries its descriptor error, and `space embed` places the prediction with it:
// each axis's variance grows by exactly the error carried through the space's map, J·Σ·Jᵀ, over
// the same file without the error.
void expect_placed_with_its_descriptor_error(const std::filesystem::path& out,
                                             const std::filesystem::path& space_file) {
  const auto predicted = read_json(out / "predicted.json");
  ASSERT_TRUE(predicted.contains("descriptor_error_covariance"));
  const auto& error = predicted["descriptor_error_covariance"];
  const auto names = error["names"].get<std::vector<std::string>>();
  EXPECT_EQ(names, space::all_paper_descriptor_names());
  EXPECT_GT(error["vibration_samples"].get<int>(), 40);  // every exemplar of the bundled catalog
  EXPECT_GT(error["friction_samples"].get<int>(), 5);    // its middle tips
  nlohmann::json without = predicted;
  without.erase("descriptor_error_covariance");
  std::ofstream(out / "predicted_without_error.json") << without.dump();
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const auto catalog = (nibrig::test::assets_dir() / "default_catalog.json").string();
  ASSERT_EQ(run_cli({"space", "embed", space_file.string(), catalog, "--predicted",
                     (out / "predicted_without_error.json").string(), "-o",
                     (out / "placed_without_error.csv").string()}),
            0);
  ::testing::internal::GetCapturedStdout();
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find("placed as if measured"), std::string::npos) << warning;
  // A damaged covariance is refused, naming the file and the field.
  const auto refused = [&](nlohmann::json damaged, const std::string& field) {
    std::ofstream(out / "damaged.json") << damaged.dump();
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    const int code = run_cli({"space", "embed", space_file.string(), catalog, "--predicted",
                              (out / "damaged.json").string()});
    ::testing::internal::GetCapturedStdout();
    const std::string error = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(code, 0) << field;
    EXPECT_NE(error.find("damaged.json"), std::string::npos) << error;
    EXPECT_NE(error.find(field), std::string::npos) << error;
  };
  nlohmann::json asymmetric = predicted;
  asymmetric["descriptor_error_covariance"]["matrix"][0][1] = 1.0;
  refused(asymmetric, "descriptor_error_covariance.matrix");
  nlohmann::json negative = predicted;
  negative["descriptor_error_covariance"]["matrix"][1][1] = -0.1;
  refused(negative, "descriptor_error_covariance.matrix[1]");
  nlohmann::json unnamed = predicted;  // without the weighted mean the 2-D map needs
  unnamed["descriptor_error_covariance"]["names"][1] = "loudness";
  refused(unnamed, "descriptor_error_covariance.names");

  const auto with_error = predicted_sds(out / "placed.csv");
  const auto without_error = predicted_sds(out / "placed_without_error.csv");

  const auto s = space::read_space_file(space_file);
  const auto& map = *s.descriptor_map;
  Eigen::MatrixXd sigma(2, 2);
  for (Eigen::Index i = 0; i < 2; ++i)
    for (Eigen::Index j = 0; j < 2; ++j) {
      const auto at = [&](Eigen::Index k) {
        const auto& name = map.descriptor_names[static_cast<std::size_t>(k)];
        return std::find(names.begin(), names.end(), name) - names.begin();
      };
      sigma(i, j) = error["matrix"][at(i)][at(j)].get<double>();
    }
  EXPECT_GT(sigma(0, 0), 0.0) << "a mix's μ is interpolated: it carries the friction error";
  const Eigen::MatrixXd jacobian =
      map.coefficients.rightCols(2) * map.descriptor_scale.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd added = jacobian * sigma * jacobian.transpose();
  for (Eigen::Index d = 0; d < 2; ++d) {
    const double grown =
        with_error[static_cast<std::size_t>(d)] * with_error[static_cast<std::size_t>(d)] -
        without_error[static_cast<std::size_t>(d)] * without_error[static_cast<std::size_t>(d)];
    // The CSV holds 8 significant digits.
    EXPECT_NEAR(grown, added(d, d), 1e-6 * (1 + added(d, d))) << "axis " << d + 1;
    EXPECT_GT(added(d, d), 0.0);
  }
}

// One design for two tools (Sec. 7): the measured DM85 tool on glass and the judged crayon on office
// paper, with tips of at most 3 mm and a cost limit that excludes pure DM85 — every candidate keeps
// to them, the optimum's group distance is its largest, its distance to the judged target is the
// one between their coordinates, and the export says which single material breaks the limit.
void expect_a_group_design_within_constraints(const std::filesystem::path& out,
                                              const std::filesystem::path& space_file,
                                              const std::vector<std::string>& coarse) {
  std::vector<std::string> args{"design", "--target", "DM854/glass", "cryon/office", "--surface", "glass",
                                "--space", space_file.string(), "--forcing", (out / "forcing.json").string(),
                                "--between", "vero,tip=1mm", "DM85,tip=4mm", "--max-tip-mm", "3", "--cost",
                                "vero=1,DM85=3", "--max-cost", "2.5", "-o", (out / "group.json").string(),
                                "--export", (out / "group").string()};
  args.insert(args.end(), coarse.begin(), coarse.end());
  ::testing::internal::CaptureStdout();
  const int code = run_cli(args);
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  const auto search = read_json(out / "group.json");
  EXPECT_EQ(search["targets"].get<std::vector<std::string>>(), (std::vector<std::string>{"DM854/glass", "cryon/office"}));
  EXPECT_EQ(search["aim"], "largest");
  for (const auto& c : search["path"]) {
    const auto point = model::design::parse_design_point(c["design"].get<std::string>());
    EXPECT_LE(point.tip_diameter_m, 0.003 * (1 + 1e-9)) << c["design"];
    EXPECT_LE(c["cost"].get<double>(), 2.5 + 1e-9) << c["design"];
    const double f = point.fraction_of("DM85");
    // The fractions times --cost; the design's text keeps 6 digits of a fraction (5e-7), times the
    // costs' difference, 2.
    EXPECT_NEAR(c["cost"].get<double>(), (1 - f) * 1.0 + f * 3.0, 1e-6);
  }
  const auto& optimum = search["optimum"];
  const auto each = optimum["target_distances"].get<std::vector<double>>();
  ASSERT_EQ(each.size(), 2u);
  EXPECT_EQ(optimum["distance"].get<double>(), std::max(each[0], each[1]));
  // The crayon was judged: its place is the space file's; the optimum's is in the search's JSON.
  const auto space = space::read_space_file(space_file);
  const auto judged = std::find(space.stimuli.begin(), space.stimuli.end(), "cryon/office") - space.stimuli.begin();
  const auto coordinates = optimum["coordinates"].get<std::vector<double>>();
  double squared = 0;
  for (std::size_t d = 0; d < coordinates.size(); ++d)
    squared += std::pow(coordinates[d] - space.coordinates(static_cast<Eigen::Index>(d), judged), 2);
  EXPECT_NEAR(each[1], std::sqrt(squared), 1e-12);
  EXPECT_TRUE(is_png(out / "group" / "stylus-sheet.png"));
  const auto recipe = read_json(out / "group" / "stylus.json");
  for (const auto& sub : recipe["substitutes"])
    EXPECT_EQ(sub.contains("outside_constraints"), sub["design"].get<std::string>().rfind("DM85:1,", 0) == 0) << sub;

  // Constraints that cannot be met, or a cost limit without costs: refused, naming what.
  const auto refused = [&](std::vector<std::string> extra, const std::string& named) {
    std::vector<std::string> bad{"design", "--target", "DM854/glass", "--surface", "glass", "--space",
                                 space_file.string(), "--forcing", (out / "forcing.json").string(), "--between",
                                 "vero,tip=1mm", "DM85,tip=4mm", "-o", (out / "refused.json").string()};
    bad.insert(bad.end(), extra.begin(), extra.end());
    ::testing::internal::CaptureStderr();
    ::testing::internal::CaptureStdout();
    const int failed = run_cli(bad);
    ::testing::internal::GetCapturedStdout();
    const std::string error = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(failed, 0) << named;
    EXPECT_NE(error.find(named), std::string::npos) << error;
  };
  refused({"--max-cost", "2"}, "--max-cost");
  refused({"--max-tip-mm", "0.5"}, "at most 0.5 mm");
  refused({"--cost", "vero=1,DM85"}, "--cost");
  EXPECT_FALSE(std::filesystem::exists(out / "refused.json"));
}

// The trial's `design … --space D/stylus.json --export D`: the recipe (D/stylus.json) would replace
// the space it searches in. Refused before the search, the space as it was.
TEST(DesignCli, AnExportOntoItsOwnSpaceIsRefusedBeforeTheSearch) {
  const auto out = nibrig::test::scratch_dir("cli_design_export_onto_space");
  const auto made = write_test_space(out);
  const auto folder = out / "D";
  std::filesystem::create_directories(folder);
  std::filesystem::rename(made, folder / "stylus.json");
  std::ifstream before_in(folder / "stylus.json");
  const std::string before((std::istreambuf_iterator<char>(before_in)), std::istreambuf_iterator<char>());
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"design", "--target", "cryon/office", "--surface", "protector", "--space",
                            (folder / "stylus.json").string(), "--between", "vero:1,tip=1mm", "DM85:1,tip=4mm",
                            "--export", folder.string()});
  const std::string printed = ::testing::internal::GetCapturedStdout();
  const std::string errors = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, 1) << errors;
  EXPECT_NE(errors.find("read as an input"), std::string::npos) << errors;
  EXPECT_EQ(printed.find("optimum"), std::string::npos) << "refused before the search: " << printed;
  std::ifstream after_in(folder / "stylus.json");
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(after_in)), std::istreambuf_iterator<char>()), before);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(folder)) ++entries;
  EXPECT_EQ(entries, 1u);
}

TEST(DesignCli, TheLineSearchOnGlassTowardsAMeasuredDm85ToolEndsAtItsDesign) {
  const auto out = nibrig::test::scratch_dir("cli_design");
  const auto space_file = write_test_space(out);
  const std::vector<std::string> coarse{"--modes", "32", "--mesh-size", "0.004"};
  std::vector<std::string> fit{"forcing", "fit", "-o", (out / "forcing.json").string()};
  fit.insert(fit.end(), coarse.begin(), coarse.end());
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli(fit), 0);
  ::testing::internal::GetCapturedStdout();

  // The target is the measured 4 mm DM85 tool on glass, placed from its descriptors; the line runs
  // from the 1 mm VeroClear design to the 4 mm DM85 one. The model predicts the DM85 end from the
  // same tool's data, so the optimum must lie at or next to that end.
  std::vector<std::string> args{"design",
                                "--target",
                                "DM854/glass",
                                "--surface",
                                "glass",
                                "--space",
                                space_file.string(),
                                "--forcing",
                                (out / "forcing.json").string(),
                                "--between",
                                "vero,tip=1mm",
                                "DM85,tip=4mm",
                                "-o",
                                (out / "search.json").string(),
                                "--plot",
                                (out / "path.png").string()};
  args.insert(args.end(), coarse.begin(), coarse.end());
  ::testing::internal::CaptureStdout();
  const int code = run_cli(args);
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  const auto search = read_json(out / "search.json");
  const auto& path = search["path"];
  ASSERT_GE(path.size(), 9u);
  const double at_vero = path[0]["distance"], at_dm85 = path[8]["distance"];
  const double best = search["optimum"]["distance"];
  EXPECT_LE(best, at_vero);
  EXPECT_LE(best, at_dm85);
  EXPECT_LT(at_dm85, at_vero);
  // Within one scan step (1/8 of the line) of the DM85 end.
  const auto optimum =
      model::design::parse_design_point(search["optimum"]["design"].get<std::string>());
  EXPECT_GE(optimum.fraction_of("DM85"), 0.875) << search["optimum"]["design"];
  EXPECT_GE(search["runners_up"].size(), 1u);
  EXPECT_TRUE(is_png(out / "path.png"));
  // A pairing the test's space never judged: placed from its descriptors.
  EXPECT_EQ(search["placed"], nlohmann::json::array({"DM854/glass"}));

  // The same search through the design grid (solved here into the test's own cache): the FEM only
  // where the grid's measured error could change the answer, an optimum the FEM solved, within that
  // error of the full search's, for fewer solves than the full search's candidates.
  {
    const nibrig::test::ScopedCacheDir cache(out / "cache");
    std::vector<std::string> guided = args;
    guided.erase(guided.end() - static_cast<long>(coarse.size()) - 4,
                 guided.end() - static_cast<long>(coarse.size()));
    guided.insert(guided.end(), {"--grid", "-o", (out / "search_grid.json").string()});
    ::testing::internal::CaptureStdout();
    const int guided_code = run_cli(guided);
    const std::string guided_text = ::testing::internal::GetCapturedStdout();
    ASSERT_EQ(guided_code, 0) << guided_text;
    const auto on_grid = read_json(out / "search_grid.json");
    const double error = on_grid["grid"]["error"];
    EXPECT_GT(error, 0.0);
    EXPECT_LT(on_grid["grid"]["fem_solves"].get<std::size_t>(), path.size());
    EXPECT_NEAR(on_grid["optimum"]["distance"].get<double>(), best, error);
    std::size_t solved = 0;
    for (const auto& c : on_grid["path"]) {
      solved += c["fem_solved"].get<bool>();
      if (c["design"] == on_grid["optimum"]["design"]) EXPECT_TRUE(c["fem_solved"].get<bool>());
    }
    EXPECT_GE(solved, 1u);
    EXPECT_LT(solved, on_grid["grid"]["fem_solves"].get<std::size_t>() + 1);
  }

  // The acceptance command (with this test's coarse FEM and its fitted model): the optimum's
  // stylus written into a new folder, one STL per region beside the 3MF, which PrusaSlicer slices.
  std::vector<std::string> exported{"design", "--target", "cryon/office", "--surface", "protector", "--space",
                                    space_file.string(), "--between", "vero:1,tip=1mm", "DM85:1,tip=4mm",
                                    "--export", (out / "printed").string(), "--forcing",
                                    (out / "forcing.json").string(), "-o", (out / "search_printed.json").string()};
  exported.insert(exported.end(), coarse.begin(), coarse.end());
  std::filesystem::remove_all(out / "printed");
  ::testing::internal::CaptureStdout();
  const int export_code = run_cli(exported);
  const std::string export_text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(export_code, 0) << export_text;
  const auto regions = model::mesh_io::read_3mf_regions(out / "printed" / "stylus.3mf");
  ASSERT_FALSE(regions.empty());
  for (const auto& region : regions)
    EXPECT_TRUE(std::filesystem::is_regular_file(out / "printed" / ("stylus-" + region.surface.name + ".stl")))
        << region.surface.name;
  const auto sliced = nibrig::test::run_program({"prusa-slicer", "--loglevel", "2", "--export-gcode",
                                                  (out / "printed" / "stylus.3mf").string(), "-o",
                                                  (out / "printed" / "stylus.gcode").string()},
                                                 out);
  EXPECT_EQ(sliced.exit_code, 0) << sliced.output;
  EXPECT_EQ(sliced.output.find("warning"), std::string::npos) << sliced.output;
  EXPECT_GT(std::filesystem::file_size(out / "printed" / "stylus.gcode"), 0u);
  // The print sheet beside them (its content: tests/ui/figures/stylus_sheet_test.cpp).
  EXPECT_TRUE(is_png(out / "printed" / "stylus-sheet.png"));
  // The recipe: the regions' volumes as the 3MF holds them, and for a mixed optimum each material
  // alone at its tip, placed, with the distances the search's own draws give (finite, at least 0).
  const auto recipe = read_json(out / "printed" / "stylus.json");
  const auto optimum_printed =
      model::design::parse_design_point(read_json(out / "search_printed.json")["optimum"]["design"].get<std::string>());
  EXPECT_EQ(recipe["design"].get<std::string>(), model::design::to_string(optimum_printed));
  ASSERT_EQ(recipe["regions"].size(), regions.size());
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const double volume = model::mechanics::enclosed_volume(regions[r].surface) * 1e9;
    EXPECT_NEAR(recipe["regions"][r]["volume_mm3"].get<double>(), volume, 1e-5 * volume);  // the 3MF's f32 mm
  }
  const std::size_t materials = optimum_printed.mix.size();
  ASSERT_EQ(recipe["substitutes"].size(), materials > 1 ? materials : 0u);
  for (const auto& sub : recipe["substitutes"]) {
    EXPECT_GE(sub["cost"].get<double>(), 0.0);
    EXPECT_GE(sub["to_target"].get<double>(), 0.0);
    EXPECT_EQ(model::design::parse_design_point(sub["design"].get<std::string>()).tip_diameter_m,
              optimum_printed.tip_diameter_m);
  }

  // A predicted tool is placed in the space beside the catalog's (Fig. 15), hollow, "predicted".
  std::vector<std::string> predict{"predict",
                                   "--design",
                                   "DM85:0.5,vero:0.5,tip=2mm",
                                   "--surface",
                                   "glass",
                                   "--forcing",
                                   (out / "forcing.json").string(),
                                   "-o",
                                   (out / "predicted.json").string()};
  predict.insert(predict.end(), coarse.begin(), coarse.end());
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli(predict), 0);
  ASSERT_EQ(run_cli({"space", "embed", space_file.string(),
                     (nibrig::test::assets_dir() / "default_catalog.json").string(), "--predicted",
                     (out / "predicted.json").string(), "-o", (out / "placed.csv").string(),
                     "--plot", (out / "placed.png").string()}),
            0);
  ::testing::internal::GetCapturedStdout();
  std::ifstream placed(out / "placed.csv");
  const std::string csv((std::istreambuf_iterator<char>(placed)), std::istreambuf_iterator<char>());
  EXPECT_NE(csv.find("\"pred:DM85:0.5,vero:0.5,tip=2mm/glass\",no,"), std::string::npos) << csv;
  EXPECT_TRUE(is_png(out / "placed.png"));
  expect_placed_with_its_descriptor_error(out, space_file);
  // A file that is not a prediction is refused, naming it and the field.
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const int not_prediction = run_cli({"space", "embed", space_file.string(),
                                      (nibrig::test::assets_dir() / "default_catalog.json").string(),
                                      "--predicted", (out / "search.json").string()});
  ::testing::internal::GetCapturedStdout();
  const std::string refused = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(not_prediction, 0);
  EXPECT_NE(refused.find("search.json"), std::string::npos) << refused;
  EXPECT_NE(refused.find("kind"), std::string::npos) << refused;

  // A target the space cannot place fails in one line.
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const int bad = run_cli({"design", "--target", "nothing/glass", "--surface", "glass", "--space",
                           space_file.string(), "--forcing", (out / "forcing.json").string()});
  ::testing::internal::GetCapturedStdout();
  const std::string error = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(bad, 2) << "an unknown --target is a usage error: " << error;
  EXPECT_NE(error.find("--target"), std::string::npos) << "names the option: " << error;
  EXPECT_NE(error.find("nothing/glass"), std::string::npos) << error;
  EXPECT_NE(error.find("choices: "), std::string::npos) << "lists what it accepts: " << error;

  expect_a_group_design_within_constraints(out, space_file, coarse);

  // A design exported for itself in a space: its sheet, and each material alone placed against it
  // (no target to measure from).
  std::vector<std::string> exported_alone{"export", "DM85:0.5,vero:0.5,tip=2mm", "-o",
                                          (out / "alone" / "stylus.3mf").string(), "--surface", "glass", "--space",
                                          space_file.string(), "--forcing", (out / "forcing.json").string()};
  exported_alone.insert(exported_alone.end(), coarse.begin(), coarse.end());
  ::testing::internal::CaptureStdout();
  const int alone_code = run_cli(exported_alone);
  const std::string alone_text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(alone_code, 0) << alone_text;
  EXPECT_TRUE(is_png(out / "alone" / "stylus-sheet.png"));
  const auto alone_recipe = read_json(out / "alone" / "stylus.json");
  ASSERT_EQ(alone_recipe["substitutes"].size(), 2u);
  for (const auto& s : alone_recipe["substitutes"]) {
    EXPECT_GT(s["cost"].get<double>(), 0.0) << s;  // each material alone lies elsewhere than the mix
    EXPECT_FALSE(s.contains("to_target")) << s;
  }

  // On a printer that cannot mix, the mix is refused and the single materials it has are offered
  // with their distance from the design: a PolyJet profile of the lab's without digital materials.
  std::string profile = [] {
    std::ifstream in(nibrig::test::assets_dir() / "printers" / "stratasys-objet260-connex.json");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }();
  profile.replace(profile.find("\"mixes_materials\": true"), 23, "\"mixes_materials\": false");
  std::ofstream(out / "no-mix.json") << profile;
  std::vector<std::string> on_printer = exported_alone;
  on_printer[3] = (out / "no_mix" / "stylus.3mf").string();
  on_printer.insert(on_printer.end(), {"--printer", (out / "no-mix.json").string()});
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const int refused_code = run_cli(on_printer);
  ::testing::internal::GetCapturedStdout();
  const std::string refused_text = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(refused_code, 1) << refused_text;
  EXPECT_NE(refused_text.find("cannot mix materials"), std::string::npos) << refused_text;
  for (const auto& s : alone_recipe["substitutes"]) {  // the same draws: the same distances, as printed
    char offered[256];
    std::snprintf(offered, sizeof offered, "%s (%.3f ± %.3f from the design in the space)",
                  s["design"].get<std::string>().c_str(), s["cost"].get<double>(), s["cost_sd"].get<double>());
    EXPECT_NE(refused_text.find(offered), std::string::npos) << offered << "\n" << refused_text;
  }
  EXPECT_FALSE(std::filesystem::exists(out / "no_mix" / "stylus.3mf"));
}

// Ctrl-C while a design search predicts its candidates: it stops at the next candidate, says so,
// and writes neither the search file nor the export.
TEST(DesignCli, CtrlCDuringTheSearchStopsItAndWritesNothing) {
  const auto folder = nibrig::test::scratch_dir("cli_design_stopped");
  const auto space_file = write_test_space(folder);
  const auto said = folder / "said.txt";
  const auto out = folder / "out";
  std::filesystem::create_directories(out);
  // -v logs the search's size when its first candidate is predicted: the search has begun.
  const pid_t pid = nibrig::test::start_cli(
      nibrig::test::with_coarse({"-v", "design", "--target", "cryon/office", "--surface", "office",
                                 "--space", space_file.string(), "--between", "vero:1,tip=1mm",
                                 "DM85:1,tip=4mm", "-o", (out / "search.json").string()}),
      {}, {}, said);
  bool searching = false;
  for (int i = 0; i < 2400 && !searching; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    searching = nibrig::test::file_text(said).find("designs to predict") != std::string::npos;
  }
  ::kill(pid, SIGINT);
  const int code = nibrig::test::wait_cli(pid);
  const std::string errors = nibrig::test::file_text(said);
  ASSERT_TRUE(searching) << "the search never began: " << errors;
  // Stopped by the library at a candidate (exit 130 from the command), not killed by the signal.
  EXPECT_EQ(code, 130) << errors;
  EXPECT_NE(errors.find("nibrig: interrupted: the design search was stopped"), std::string::npos)
      << errors;
  EXPECT_TRUE(std::filesystem::is_empty(out));
}

}  // namespace
}  // namespace nibrig::ui::cli
