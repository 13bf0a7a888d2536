// The paper's recordings read under names that say nothing (copies of real files in a scratch
// folder): the format from the header, the tool and surface as stated, and the same samples as
// when the file carries its documented name.
#include "model/io/paper_recording.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

std::filesystem::path piovarci() { return nibrig::test::shared_data() / "piovarci2018"; }
const std::filesystem::path kVibration = "vibration/arm2/arm_cryon_note.csv.gz";
const std::filesystem::path kFriction = "friction/printed/DM851_note_2.2N_13.3_1.csv.gz";

std::filesystem::path copy_as(const std::filesystem::path& real, const std::string& name) {
  const auto dir = nibrig::test::scratch_dir("paper_recording_" + name);
  std::filesystem::copy_file(piovarci() / real, dir / name);
  return dir / name;
}

StatedRecording stating(std::optional<std::string> tool, std::optional<std::string> surface,
                        std::optional<double> load = {}, std::optional<double> lever = {}) {
  StatedRecording stated;
  stated.tool = std::move(tool);
  stated.surface = std::move(surface);
  stated.normal_load_N = load;
  stated.lever_factor = lever;
  return stated;
}

TEST(PaperFormat, FromTheHeaderOfRealFiles) {
  EXPECT_EQ(paper_format_from_header(copy_as(kVibration, "a.csv.gz")), PaperFormat::vibration);
  EXPECT_EQ(paper_format_from_header(copy_as(kFriction, "b.csv.gz")), PaperFormat::friction);
}

TEST(PaperFormat, BlankAccelerometerHeaderIsTheAccelerometers) {
  // Some real accelerometer files carry ",,,,," as their header (paper_vibration.hpp).
  const auto dir = nibrig::test::scratch_dir("paper_format_blank");
  nibrig::test::write_text(dir / "x.csv", ",,,,,\n0,1515589189348,1,0,0,1\n");
  EXPECT_EQ(paper_format_from_header(dir / "x.csv"), PaperFormat::vibration);
}

TEST(PaperFormat, AnotherHeaderIsRefusedNamingBoth) {
  const auto dir = nibrig::test::scratch_dir("paper_format_other");
  nibrig::test::write_text(dir / "x.csv", "a,b,c\n1,2,3\n");
  expect_message_names(format_error_of([&] { paper_format_from_header(dir / "x.csv"); }),
                       {"x.csv", "line 1", "xAccel", "TimeStamp,X,Y,Z"});
}

TEST(PaperRecording, VibrationUnderAnyNameReadsTheSameSamplesAsStated) {
  const auto original = read_paper_vibration(piovarci() / kVibration);
  const auto copy = copy_as(kVibration, "arm_DM85_25_vero_75_1_note.csv.gz");
  const auto stated = read_paper_vibration(copy, stating("mixA", "note"));
  EXPECT_EQ(stated.name.tool, "mixA");
  EXPECT_EQ(stated.name.surface, "note");
  // The label changes, the recording does not: every sample exactly as read under its own name.
  EXPECT_EQ(stated.acceleration_m_s2, original.acceleration_m_s2);
  EXPECT_EQ(stated.timestamp_gaps, original.timestamp_gaps);
}

TEST(PaperRecording, VibrationUnderAnyNameWithoutAStatementSaysWhatToState) {
  const auto copy = copy_as(kVibration, "any_name.csv.gz");
  expect_message_names(format_error_of([&] { read_paper_vibration(copy, stating("mixA", {})); }),
                       {"any_name.csv.gz", "unparsable file name", "state its tool and surface"});
}

TEST(PaperRecording, AStatedToolDropsTheNamesMaterialAndTip) {
  const auto copy = copy_as(kVibration, "arm_DM85_2_note.csv.gz");
  EXPECT_TRUE(read_paper_vibration(copy, StatedRecording{}).name.tip_diameter_m.has_value());
  const auto stated = read_paper_vibration(copy, stating("mixA", {}));
  // DM85 at 2 mm described the tool the name gave, not mixA; the surface still comes from the name.
  EXPECT_EQ(stated.name.tool, "mixA");
  EXPECT_TRUE(stated.name.material.empty());
  EXPECT_FALSE(stated.name.tip_diameter_m.has_value());
  EXPECT_EQ(stated.name.surface, "note");
}

TEST(PaperRecording, FrictionUnderAnyNameNeedsTheLeverFactor) {
  const auto copy = copy_as(kFriction, "run7.csv.gz");
  expect_message_names(
      format_error_of([&] { read_paper_friction(copy, stating("mixA", "note", 2.2)); }),
      {"run7.csv.gz", "lever factor"});
  const auto original = read_paper_friction(piovarci() / kFriction);
  const auto stated = read_paper_friction(copy, stating("mixA", "note", 2.2, 13.3));
  EXPECT_EQ(stated.name.tool, "mixA");
  // Same lever as the original's name, so the same newtons to the last bit.
  EXPECT_EQ(stated.tangential_force_N, original.tangential_force_N);
  EXPECT_DOUBLE_EQ(stated.sample_rate_hz, original.sample_rate_hz);
}

TEST(PaperRecording, AStatedLeverFactorReplacesTheNames) {
  const auto copy = copy_as(kFriction, kFriction.filename().string());
  const auto original = read_paper_friction(copy, StatedRecording{});
  const auto doubled = read_paper_friction(copy, stating({}, {}, {}, 26.6));
  ASSERT_EQ(doubled.tangential_force_N.size(), original.tangential_force_N.size());
  // Force at the tip = counts / 403.2 / lever: twice the lever, half the force.
  for (std::size_t i = 0; i < original.tangential_force_N.size(); i += 997)
    EXPECT_NEAR(doubled.tangential_force_N[i], original.tangential_force_N[i] / 2, 1e-12);
}

TEST(PaperRecording, ExplicitNamesAreChecked) {
  const auto copy = copy_as(kFriction, "run8.csv.gz");
  EXPECT_THROW(read_paper_friction(copy, FrictionFileName{"t", "s", 2.2, 0.0, 1}),
               std::invalid_argument);
  EXPECT_THROW(read_paper_vibration(copy_as(kVibration, "v.csv.gz"), VibrationFileName{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::io
