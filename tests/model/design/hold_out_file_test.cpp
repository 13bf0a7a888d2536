// The hold-out table written and read back: the errors per speed and over all speeds come back bit
// for bit (written with the digits that read back to the same double), a neighbour that was not
// measured stays an empty field, and a tool that could not be predicted keeps its reason.
#include "model/design/hold_out_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

// Two predicted tools with errors that are not round numbers, one of them without a measured
// upper neighbour, and one tool that could not be predicted.
std::vector<InterpolatedPrediction> hold_out_file_predictions() {
  std::vector<InterpolatedPrediction> out;
  for (int k = 0; k < 2; ++k) {
    InterpolatedPrediction p;
    p.tool = k == 0 ? "vero2" : "DM852";
    p.surface = "office";
    p.material = k == 0 ? "vero" : "DM85";
    p.tip_diameter_m = 0.002;
    p.comparison.interpolated = {1.0 / 3 + k, {0.1 / 7, 2.0 / 9 + k}};
    p.comparison.baselines = {{DesignPoint{}, {1.5 / 7, {0.3, 0.7 / 3}}},
                              {DesignPoint{}, {2.5 / 7, {0.4, 1.7 / 3}}}};
    p.measured_neighbour_rms_db = {3.0 / 11, k == 0 ? 4.0 / 13 : -1.0};
    out.push_back(p);
  }
  InterpolatedPrediction lost;
  lost.tool = "DM952";
  lost.surface = "stone";
  lost.not_predictable = "no other tool was measured on stone, so nothing to fit";
  out.push_back(lost);
  return out;
}

std::string hold_out_file_slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HoldOutFile, RoundTripsEveryErrorExactly) {
  const auto predictions = hold_out_file_predictions();
  const std::vector<double> speeds{0.017, 0.25};
  const HoldOutColumns columns = tip_hold_out_columns(0.001, 0.004);
  EXPECT_EQ(columns.baseline[0], "tip_1mm_curve_rms_db");
  const auto file = nibrig::test::scratch_dir("hold_out_file") / "holdout.csv";
  write_hold_out_csv(file, predictions, speeds, columns);
  EXPECT_EQ(hold_out_file_slurp(file), hold_out_csv_text(predictions, speeds, columns));

  const HoldOutTable table = read_hold_out_csv(file);
  EXPECT_EQ(table.columns.baseline, columns.baseline);
  EXPECT_EQ(table.columns.measured, columns.measured);
  ASSERT_EQ(table.rows.size(), 2u * (speeds.size() + 1) + 1);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& c = predictions[k].comparison;
    for (std::size_t s = 0; s <= speeds.size(); ++s) {
      const HoldOutRow& row = table.rows[k * (speeds.size() + 1) + s];
      EXPECT_EQ(row.tool, predictions[k].tool);
      const bool all = s == speeds.size();
      ASSERT_EQ(row.speed_mm_s.has_value(), !all);
      if (!all) {
        EXPECT_NEAR(*row.speed_mm_s, speeds[s] * 1e3, 1e-9);  // {:g} of 17 and 250 mm/s
        EXPECT_EQ(row.interpolated_rms_db, c.interpolated.rms_db_by_speed[s]);
        EXPECT_EQ(row.baseline_rms_db[1], c.baselines[1].error.rms_db_by_speed[s]);
        EXPECT_FALSE(row.measured_rms_db[0].has_value());  // measured neighbours: over all only
      } else {
        EXPECT_EQ(row.interpolated_rms_db, c.interpolated.rms_db);
        EXPECT_EQ(row.baseline_rms_db[0], c.baselines[0].error.rms_db);
        EXPECT_EQ(row.measured_rms_db[0], predictions[k].measured_neighbour_rms_db[0]);
      }
      EXPECT_TRUE(row.not_predictable.empty());
    }
  }
  EXPECT_EQ(table.rows[5].measured_rms_db[1], std::nullopt);  // DM852's upper was not measured
  const HoldOutRow& lost = table.rows.back();
  EXPECT_EQ(lost.tool, "DM952");
  EXPECT_FALSE(lost.speed_mm_s.has_value());
  EXPECT_FALSE(lost.interpolated_rms_db.has_value());
  EXPECT_EQ(lost.not_predictable, predictions[2].not_predictable);  // its comma inside the quotes
}

TEST(HoldOutFile, MaterialColumnsNameTheMixAndAnotherHeaderIsRefused) {
  const HoldOutColumns columns = material_hold_out_columns("vero", "DM85");
  EXPECT_EQ(columns.baseline[1], "DM85_curve_rms_db");
  EXPECT_EQ(columns.measured[0], "measured_vero_rms_db");
  const auto file = nibrig::test::scratch_dir("hold_out_file_bad") / "other.csv";
  {
    std::ofstream(file) << "tool,surface,speed_mm_s\nvero2,office,all\n";
  }
  try {
    read_hold_out_csv(file);
    FAIL() << "read a table that is not a hold-out table";
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("other.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not_predictable"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::model::design
