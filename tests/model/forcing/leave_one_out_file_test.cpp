// The leave-one-out table written and read back: every number comes back bit for bit (written
// with the digits that read back to the same double), and a tool that could not be predicted
// keeps its reason and its empty fields.
#include "model/forcing/leave_one_out_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "model/forcing/descriptor_error.hpp"
#include "model/io/format_error.hpp"
#include "tests/model/forcing/synthetic_exemplars.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::forcing {
namespace {

std::string loo_file_slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(LeaveOneOutFile, RoundTripsEveryErrorExactlyAndTheReasonsInWords) {
  auto truth = test::make_synthetic_truth();
  test::add_log_noise(truth.exemplars, 0.1, 5);  // errors that are not round numbers
  ForcingExemplar alone = truth.exemplars.front();
  alone.tool = "vero2";
  alone.surface = "d";  // the only tool on surface d: not predictable, with a reason
  truth.exemplars.push_back(alone);
  const std::vector<std::size_t> held{0, 1, truth.exemplars.size() - 1};
  LeaveOneOut loo = leave_one_out(truth.exemplars, held);
  ASSERT_TRUE(loo.results[0].predictable);
  ASSERT_FALSE(loo.results[2].predictable);
  // A descriptor error as leave_one_out gives one with a threshold curve; a quote in a reason.
  loo.results[0].descriptor_error = DescriptorError{"", "", 0.0123456789, {}};
  loo.results[2].reason += " (\"d\", 1 tool)";
  const std::vector<double> speeds = truth.exemplars.front().measured.speeds_m_s;

  const auto file = nibrig::test::scratch_dir("loo_file") / "loo.csv";
  write_leave_one_out_csv(file, loo, speeds);
  EXPECT_EQ(loo_file_slurp(file), leave_one_out_csv_text(loo, speeds));
  const LeaveOneOutTable table = read_leave_one_out_csv(file);
  ASSERT_EQ(table.speeds_mm_s.size(), speeds.size());
  for (std::size_t s = 0; s < speeds.size(); ++s)
    EXPECT_NEAR(table.speeds_mm_s[s], speeds[s] * 1e3, 1e-9);  // {:g}: six digits of a round speed
  ASSERT_EQ(table.rows.size(), loo.results.size());
  for (std::size_t k = 0; k < loo.results.size(); ++k) {
    const HeldOutResult& r = loo.results[k];
    const LeaveOneOutRow& row = table.rows[k];
    EXPECT_EQ(row.tool, r.tool);
    EXPECT_EQ(row.surface, r.surface);
    EXPECT_EQ(row.predictable, r.predictable);
    if (r.predictable) {
      EXPECT_EQ(row.rms_db, r.rms_db);
      EXPECT_EQ(row.baseline_rms_db, r.baseline_rms_db);
      for (std::size_t s = 0; s < speeds.size(); ++s)
        EXPECT_EQ(row.rms_db_by_speed[s], r.rms_db_by_speed[s]);
    } else {
      EXPECT_FALSE(row.rms_db.has_value());
      for (const auto& e : row.rms_db_by_speed) EXPECT_FALSE(e.has_value());
    }
  }
  ASSERT_TRUE(table.rows[0].weighted_mean_error_percent.has_value());
  EXPECT_EQ(*table.rows[0].weighted_mean_error_percent, percent_off(0.0123456789));
  EXPECT_FALSE(table.rows[1].weighted_mean_error_percent.has_value());
  // The writer turns a reason's double quotes into single ones: the field stays one field.
  std::string reason = loo.results[2].reason;
  std::replace(reason.begin(), reason.end(), '"', '\'');
  EXPECT_EQ(table.rows[2].reason, reason);
  EXPECT_NE(reason.find("('d', 1 tool)"), std::string::npos) << reason;
}

TEST(LeaveOneOutFile, RefusesAnotherTableNamingTheFile) {
  const auto file = nibrig::test::scratch_dir("loo_file_bad") / "not_loo.csv";
  {
    std::ofstream(file) << "tool,surface,rms_db\nvero1,a,1.5\n";
  }
  try {
    read_leave_one_out_csv(file);
    FAIL() << "read a table that is not a leave-one-out table";
  } catch (const io::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("not_loo.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("weighted_mean_error_percent"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace nibrig::model::forcing
