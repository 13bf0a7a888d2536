// A stylus's print sheet: what the export's sheet holds (the prediction's spectrum point for point,
// the design placed with its region at the χ² radius, the targets' distances and the regions'
// volumes as printed) and what export_stylus writes — or, refused, does not.
#include "ui/figures/stylus_sheet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>

#include "model/io/bundled_assets.hpp"
#include "model/io/printer_profile.hpp"
#include "model/mechanics/region_surface.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::ui::figures {
namespace {

namespace design = model::design;
namespace fs = std::filesystem;

design::PredictionSetup bundled_setup() {
  design::PredictionSetup setup;
  setup.materials = model::mechanics::read_material_table(model::io::default_materials());
  setup.template_design = model::mechanics::read_design(model::io::default_stylus_design(), setup.materials);
  setup.modes = 4;
  return setup;
}

// A prediction as the sheet reads it: two speeds over five frequencies, one bin silent.
design::PredictedTool sample_tool(const design::DesignPoint& point) {
  design::PredictedTool tool;
  tool.point = point;
  tool.surface = "protector";
  tool.mu = 0.27;
  tool.first_mode_hz = 2345.0;
  tool.spectrum.frequencies_hz = {100, 200, 300, 400, 500};
  tool.spectrum.speeds_m_s = {0.05, 0.15};
  tool.spectrum.amplitude_m_s2 = {{1e-3, 2e-3, 0.0, 4e-3, 5e-3}, {2e-3, 3e-3, 4e-3, 5e-3, 6e-3}};
  return tool;
}

// Three judged stimuli in a 2-D space.
model::space::SpaceFile sample_space() {
  model::space::SpaceFile s;
  s.stimuli = {"cryon/office", "pencil/office", "vero/glass"};
  s.coordinates = Eigen::MatrixXd(2, 3);
  s.coordinates << 0.0, 1.0, -1.0, 0.0, 0.5, 0.5;
  return s;
}

model::space::Placement placement(double x, double y, double sx, double sy) {
  model::space::Placement p;
  p.mean = Eigen::Vector2d(x, y);
  p.covariance = Eigen::Vector2d(sx * sx, sy * sy).asDiagonal();
  return p;
}

// Every "<number> <unit>" or "distance <number> ± <number>" of the sheet's lines, as numbers.
std::vector<double> numbers_in(const std::string& text, const std::regex& pattern) {
  std::vector<double> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator(); ++it)
    for (std::size_t k = 1; k < it->size(); ++k) out.push_back(std::stod((*it)[k].str()));
  return out;
}

TEST(StylusSheet, HoldsThePredictionThePlacementAndTheDistancesAsGiven) {
  const auto point = design::parse_design_point("DM85:0.62,vero:0.38,tip=2.7mm");
  const auto print = design::stylus_print(bundled_setup(), point);
  const auto files = design::stylus_files("out/stylus.3mf", print);
  const auto tool = sample_tool(point);
  const auto space = sample_space();
  StylusSheetInputs inputs{&tool, &space, placement(0.3, -0.2, 0.4, 0.1), {}};
  inputs.targets.push_back({"cryon/office", std::nullopt, 0.4567, 0.0891});
  inputs.targets.push_back({"crayon/glass", placement(2.0, 1.0, 0.2, 0.2), 1.2345, 0.2468});
  const auto sheet = stylus_sheet(print, files, inputs);

  // The spectrum, one curve per speed, its silent bin left out (no place on a log axis).
  ASSERT_TRUE(sheet.line_plot);
  ASSERT_EQ(sheet.line_plot->series.size(), 2u);
  EXPECT_EQ(sheet.line_plot->series[0].x, (std::vector<double>{100, 200, 400, 500}));
  EXPECT_EQ(sheet.line_plot->series[0].y, (std::vector<double>{1e-3, 2e-3, 4e-3, 5e-3}));
  EXPECT_EQ(sheet.line_plot->series[1].y, tool.spectrum.amplitude_m_s2[1]);

  // The space: its three stimuli, the placed target, and the design at its placement with the
  // 68 % and 95 % ellipses of its covariance: semi-axes σ·sqrt(-2 ln(1 - p)), the χ² quantile of
  // two degrees of freedom in closed form.
  ASSERT_TRUE(sheet.scatter_plot);
  ASSERT_EQ(sheet.scatter_plot->points.size(), 5u);
  const auto& placed_target = sheet.scatter_plot->points[3];
  EXPECT_EQ(placed_target.label, "crayon/glass");
  EXPECT_DOUBLE_EQ(placed_target.x, 2.0);
  const auto& me = sheet.scatter_plot->points[4];
  EXPECT_DOUBLE_EQ(me.x, 0.3);
  EXPECT_DOUBLE_EQ(me.y, -0.2);
  EXPECT_TRUE(me.hollow);
  ASSERT_EQ(me.regions.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const double r = std::sqrt(-2.0 * std::log(1.0 - (k == 0 ? 0.68 : 0.95)));
    const double a = std::max(me.regions[k].semi_axis_1, me.regions[k].semi_axis_2);
    const double b = std::min(me.regions[k].semi_axis_1, me.regions[k].semi_axis_2);
    EXPECT_NEAR(a, 0.4 * r, 1e-9) << k;  // eigen-decomposition round-off
    EXPECT_NEAR(b, 0.1 * r, 1e-9) << k;
  }

  std::string text;
  for (const auto& line : sheet.lines) text += line.text + "\n";
  // The distances as printed: three decimals, so within half a unit of the last.
  const auto distances = numbers_in(text, std::regex(R"(distance ([0-9.]+) ± ([0-9.]+))"));
  ASSERT_EQ(distances.size(), 4u) << text;
  const double given[] = {0.4567, 0.0891, 1.2345, 0.2468};
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(distances[k], given[k], 5e-4) << text;
  // The regions' volumes as the printed surfaces enclose them, to the one decimal printed.
  const auto volumes = numbers_in(text, std::regex(R"(([0-9.]+) mm3)"));
  ASSERT_EQ(volumes.size(), print.regions.size()) << text;
  for (std::size_t r = 0; r < volumes.size(); ++r)
    EXPECT_NEAR(volumes[r], model::mechanics::enclosed_volume(print.regions[r].surface) * 1e9, 0.05);
  const auto mu = numbers_in(text, std::regex(R"(mu ([0-9.]+))"));
  ASSERT_EQ(mu.size(), 1u) << text;
  EXPECT_NEAR(mu[0], 0.27, 5e-4);
}

TEST(StylusSheet, WithoutAPredictionOrASpaceTheSheetHasNoFigures) {
  const auto point = design::parse_design_point("vero,tip=2mm");
  const auto print = design::stylus_print(bundled_setup(), point);
  const auto sheet = stylus_sheet(print, design::stylus_files("stylus.3mf", print), {});
  EXPECT_FALSE(sheet.line_plot);
  EXPECT_FALSE(sheet.scatter_plot);
  EXPECT_FALSE(sheet.lines.empty());
}

TEST(StylusSheet, ExportWritesTheFilesAndTheSheetOrNothingWhenRefused) {
  const auto dir = nibrig::test::scratch_dir("stylus_sheet_export");
  const auto point = design::parse_design_point("DM85:0.5,vero:0.5,tip=2mm");
  const auto print = design::stylus_print(bundled_setup(), point);
  const auto tool = sample_tool(point);
  const auto space = sample_space();

  // A placement of three dimensions in a 2-D space: refused before anything is written.
  model::space::Placement wrong;
  wrong.mean = Eigen::Vector3d(0, 0, 0);
  wrong.covariance = Eigen::Matrix3d::Identity();
  EXPECT_THROW(export_stylus(dir / "refused" / "stylus.3mf", print, {&tool, &space, wrong, {}}),
               std::invalid_argument);
  EXPECT_THROW(export_stylus(dir / "refused" / "stylus.3mf", print, {&tool, nullptr, placement(0, 0, 1, 1), {}}),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir / "refused"));

  const auto written = export_stylus(dir / "stylus.3mf", print, {&tool, &space, placement(0, 0, 0.2, 0.2), {}});
  EXPECT_EQ(written.sheet, dir / "stylus-sheet.png");
  for (const auto& f : {written.files.three_mf, written.files.recipe, written.sheet}) EXPECT_TRUE(fs::is_regular_file(f)) << f;
  for (const auto& f : written.files.stls) EXPECT_TRUE(fs::is_regular_file(f)) << f;
  std::ifstream png(written.sheet, std::ios::binary);
  char signature[8] = {};
  png.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
}

TEST(StylusSheet, APrintersSettingsAndTheMaterialsBasisAreOnTheSheet) {
  auto print = design::stylus_print(bundled_setup(), design::parse_design_point("PLA,tip=2mm"));
  print.printer = model::io::read_printer_profile(nibrig::test::assets_dir() / "printers" / "prusa-mk3s.json");
  const auto sheet = stylus_sheet(print, design::stylus_files("out/stylus.3mf", print), {});
  std::string text;
  for (const auto& line : sheet.lines) text += line.text + "\n";
  EXPECT_NE(text.find("PLA, 9"), std::string::npos) << text;
  EXPECT_NE(text.find("(datasheet values, not calibrated)"), std::string::npos) << text;
  EXPECT_NE(text.find("FDM, 100% infill (rectilinear), 2 perimeters, 0.15 mm layers, 0.4 mm nozzle"), std::string::npos)
      << text;
  EXPECT_NE(text.find("slice: prusa-slicer --load stylus.ini --export-gcode stylus.3mf"), std::string::npos) << text;
  EXPECT_NE(text.find("stylus.ini (the slicer's settings)"), std::string::npos) << text;
}

}  // namespace
}  // namespace nibrig::ui::figures
