#include "rig/pen/pen_force_file.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig::pen {
namespace {

// An environment variable set for one scope and put back as it was.
class PenScopedEnv {
 public:
  PenScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      ::setenv(name, value, 1);
    else
      ::unsetenv(name);
  }
  ~PenScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

PenCalibration measured_pen() {
  PenCalibration c;
  c.name = "Wacom Pro Pen 2";
  c.created = "2026-11-27T14:05:00Z";
  c.method = "kitchen scale";
  c.curve = PressureCurve({{0.0, 0.0}, {0.21, 0.49}, {0.47, 1.47}, {0.68, 2.94}});
  c.holds = {{0.49, 0.21, 0.004, 66}, {1.47, 0.47, 0.006, 67}, {2.94, 0.68, 0.009, 66}};
  return c;
}

TEST(PenForceFile, ACalibrationIsStoredByNameAndReadBack) {
  const auto dir = nibrig::test::scratch_dir("pen_force_store");
  const PenScopedEnv pens("NIBRIG_PENS", dir.c_str());
  EXPECT_EQ(pen_curve_path("Wacom Pro Pen 2"), dir / "Wacom_Pro_Pen_2.json");
  EXPECT_EQ(pen_curve_path("../x"), dir / ".._x.json");

  const PenCurveChoice before = pen_curve_for("Wacom Pro Pen 2");
  EXPECT_TRUE(before.is_default);
  EXPECT_TRUE(before.file.empty());
  EXPECT_EQ(before.curve.points().size(), default_pressure_curve().points().size());

  const PenCalibration written = measured_pen();
  write_pen_file(pen_curve_path(written.name), written);
  const PenCalibration read = read_pen_file(pen_curve_path(written.name));
  EXPECT_EQ(read.name, written.name);
  EXPECT_EQ(read.created, written.created);
  EXPECT_EQ(read.method, written.method);
  ASSERT_EQ(read.curve.points().size(), written.curve.points().size());
  for (std::size_t i = 0; i < read.curve.points().size(); ++i) {
    EXPECT_EQ(read.curve.points()[i].pressure, written.curve.points()[i].pressure);
    EXPECT_EQ(read.curve.points()[i].force_n, written.curve.points()[i].force_n);
  }
  ASSERT_EQ(read.holds.size(), 3u);
  EXPECT_EQ(read.holds[1].pressure_sd, 0.006);
  EXPECT_EQ(read.holds[1].samples, 67u);

  const PenCurveChoice after = pen_curve_for("Wacom Pro Pen 2");
  EXPECT_FALSE(after.is_default);
  EXPECT_EQ(after.file, dir / "Wacom_Pro_Pen_2.json");
  EXPECT_NEAR(after.curve.force_n(0.47), 1.47, 1e-12);
  EXPECT_TRUE(pen_curve_for("another pen").is_default);
}

TEST(PenForceFile, TheFolderFollowsXdgDataHomeThenHome) {
  const PenScopedEnv pens("NIBRIG_PENS", nullptr);
  {
    const PenScopedEnv xdg("XDG_DATA_HOME", "/tmp/xdg-data");
    EXPECT_EQ(pen_folder(), std::filesystem::path("/tmp/xdg-data/nibrig/pens"));
  }
  const PenScopedEnv xdg("XDG_DATA_HOME", nullptr);
  const PenScopedEnv home("HOME", "/home/artist");
  EXPECT_EQ(pen_curve_path("pen"),
            std::filesystem::path("/home/artist/.local/share/nibrig/pens/pen.json"));
}

// Writes `text` as a pen file and expects the reader to refuse it naming the file and saying
// `part`.
void expect_pen_file_refused(const std::string& text, const std::string& part) {
  const auto file = nibrig::test::scratch_dir("pen_force_refusals") / "broken pen.json";
  std::ofstream(file) << text;
  try {
    read_pen_file(file);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const model::io::FormatError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("broken pen.json"), std::string::npos) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

const char* const kPenFileHead =
    R"({"format": "nibrig-pen", "version": 1, "name": "p", "created": "2026-11-27T14:05:00Z",
        "method": "", "holds": [], )";

TEST(PenForceFile, BadFilesAreRefusedNamingTheFileThePlaceAndWhatWasExpected) {
  expect_pen_file_refused(R"({"format": "nibrig-pen", "version": 1,)", "line");
  expect_pen_file_refused(R"({"format": "nibrig-pen", "version": 1, "name": "p",
      "created": "2026-11-27T14:05:00Z", "method": "", "holds": []})",
                          "missing field");
  expect_pen_file_refused(std::string(kPenFileHead) + R"("points": [])" + "}", "'points'");
  expect_pen_file_refused(
      std::string(kPenFileHead) +
          R"("points": [{"pressure": 0, "force_n": 0}, {"pressure": 0.5, "force_n": 2},
                                  {"pressure": 0.4, "force_n": 3}]})",
      "field 'points[2]': expected pressures rising");
  expect_pen_file_refused(std::string(kPenFileHead) +
                              R"("points": [{"pressure": 0, "force_n": 0}, {"pressure": 0.5}]})",
                          "points[1].force_n");
  expect_pen_file_refused(
      std::string(kPenFileHead) +
          R"("points": [{"pressure": 0, "force_n": 0}, {"pressure": 1.5, "force_n": 2}]})",
      "points[1].pressure");
  expect_pen_file_refused(R"({"format": "nibrig-actuator", "version": 1})",
                          "expected \"nibrig-pen\"");
}

// A stored file that cannot be read is an error, never the default in silence.
TEST(PenForceFile, ABrokenStoredCalibrationIsNotReplacedByTheDefault) {
  const auto dir = nibrig::test::scratch_dir("pen_force_broken_store");
  const PenScopedEnv pens("NIBRIG_PENS", dir.c_str());
  std::ofstream(pen_curve_path("pen")) << "{";
  EXPECT_THROW(pen_curve_for("pen"), model::io::FormatError);
}

}  // namespace
}  // namespace nibrig::rig::pen
