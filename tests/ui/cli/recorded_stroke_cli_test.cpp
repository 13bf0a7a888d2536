// A pen stroke recorded with the drawing writer (model/io/drawing_trajectory_writer.hpp) replayed
// by `nibrig render --trajectory`, as a user would after recording one; and damaged recordings
// refused as the paper's own files are.
#include <gtest/gtest.h>
#include <sndfile.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "model/io/drawing_trajectory_writer.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;

// Three holds of one speed each, 1.5 s long, at the paper's 2.2 N with the tip down: a pen going
// round a 40 mm circle at 133 Hz.
constexpr double kHoldSeconds = 1.5;
constexpr double kHoldSpeeds_mm_s[] = {40.0, 120.0, 240.0};
constexpr double kRecordedRate_hz = 133.0;

std::filesystem::path record_three_speed_stroke(const std::filesystem::path& dir) {
  const auto file = dir / model::io::drawing_file_name("pen", "tablet", "three-speeds");
  model::io::DrawingTrajectoryWriter writer(file, {1700000000000LL, 0.0});
  const int frames = static_cast<int>(std::lround(3 * kHoldSeconds * kRecordedRate_hz));
  double arc_mm = 0.0;
  for (int k = 0; k <= frames; ++k) {
    const double t = k / kRecordedRate_hz;
    if (k > 0)
      arc_mm += kHoldSpeeds_mm_s[std::min(2, static_cast<int>((t - 1e-9) / kHoldSeconds))] /
                kRecordedRate_hz;
    model::io::DrawingFrame f;
    f.time_s = t;
    f.x_m = (100.0 + 40.0 * std::cos(arc_mm / 40.0)) * 1e-3;
    f.y_m = (100.0 + 40.0 * std::sin(arc_mm / 40.0)) * 1e-3;
    f.normal_force_N = 2.2;
    f.touching = true;
    writer.append(f);
  }
  writer.close();
  return file;
}

std::vector<float> read_replay_wav(const std::filesystem::path& file, double& rate) {
  SF_INFO info{};
  SNDFILE* f = sf_open(file.c_str(), SFM_READ, &info);
  if (!f) return {};
  std::vector<float> x(static_cast<std::size_t>(info.frames));
  sf_read_float(f, x.data(), info.frames);
  sf_close(f);
  rate = info.samplerate;
  return x;
}

double replay_rms_between(const std::vector<float>& x, double rate, double from_s, double to_s) {
  const auto a = static_cast<std::size_t>(from_s * rate), b = static_cast<std::size_t>(to_s * rate);
  double sum = 0.0;
  for (std::size_t i = a; i < b && i < x.size(); ++i) sum += double{x[i]} * x[i];
  return std::sqrt(sum / static_cast<double>(b - a));
}

double replay_db(double ratio) { return 20.0 * std::log10(ratio); }

TEST(RecordedStrokeCli, RenderReplaysARecordedStrokeLoudWhereItWasFast) {
  const auto out = nibrig::test::scratch_dir("cli_recorded_stroke");
  const auto recording = record_three_speed_stroke(out);
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"render", "--tool", "cryon", "--surface", "office", "--trajectory",
                            recording.string(), "-o", (out / "replay.wav").string()});
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  EXPECT_NE(text.find("trajectory " + recording.filename().string()), std::string::npos) << text;
  double rate = 0.0;
  const auto replay = read_replay_wav(out / "replay.wav", rate);
  // The stroke's own length: its last frame at 4.5 s.
  ASSERT_NEAR(static_cast<double>(replay.size()) / rate, 3 * kHoldSeconds, 0.01);

  // Each hold against the same tool rendered at that constant speed: the replay's level must be the
  // level of the speed the recording holds. The first 0.3 s of a hold are left out, for the
  // voice's modes to settle after the step.
  double previous_rms = 0.0;
  for (int hold = 0; hold < 3; ++hold) {
    SCOPED_TRACE("hold at " + std::to_string(kHoldSpeeds_mm_s[hold]) + " mm/s");
    const auto constant = out / ("constant" + std::to_string(hold) + ".wav");
    ::testing::internal::CaptureStdout();
    const int constant_code =
        run_cli({"render", "--tool", "cryon", "--surface", "office", "--speed",
                 std::to_string(kHoldSpeeds_mm_s[hold]), "--seconds", std::to_string(kHoldSeconds),
                 "-o", constant.string()});
    const std::string constant_text = ::testing::internal::GetCapturedStdout();
    ASSERT_EQ(constant_code, 0) << constant_text;
    double constant_rate = 0.0;
    const auto reference = read_replay_wav(constant, constant_rate);
    const double reference_rms = replay_rms_between(reference, constant_rate, 0.3, kHoldSeconds);
    const double start = hold * kHoldSeconds;
    const double replay_rms = replay_rms_between(replay, rate, start + 0.3, start + kHoldSeconds);
    std::printf("hold %.0f mm/s: replay rms %.5f, constant render %.5f (%+.2f dB)\n",
                kHoldSpeeds_mm_s[hold], replay_rms, reference_rms,
                replay_db(replay_rms / reference_rms));
    // The two are different stretches of the forcing's noise: over 1.2 s at 120 mm/s, seeds 1-6
    // give levels within 0.52 dB (σ ≈ 0.18 dB), so the difference of two has σ ≈ 0.26 dB and
    // ±1 dB is about 4σ. The level rises about 9 dB a decade of speed here, so a replayed speed a
    // third off (a wrong frame rate, mm/frame taken for mm/s is far worse) falls outside.
    EXPECT_NEAR(replay_db(replay_rms / reference_rms), 0.0, 1.0);
    // Louder where faster: the constant renders rise 4.3 dB from 40 to 120 mm/s and 5.4 dB from
    // 120 to 240; 3 dB leaves the two windows' scatter room.
    if (hold > 0) {
      EXPECT_GT(replay_db(replay_rms / previous_rms), 3.0);
    }
    previous_rms = replay_rms;
  }
}

// The same damage done to a recording and to a copy of the authors' file is refused with the same
// message (but for the file's name and the values quoted from it), exit 1, and nothing written.
TEST(RecordedStrokeCli, DamagedRecordingsAreRefusedAsThePapersFilesAre) {
  const auto out = nibrig::test::scratch_dir("cli_recorded_damaged");
  const auto recording = record_three_speed_stroke(out);
  const auto paper =
      nibrig::test::shared_data() / "piovarci2018" / "drawing" / "charc_paper_ball.csv.gz";
  const auto damaged_lines_of = [](const std::filesystem::path& file) {
    gzFile gz = gzopen(file.c_str(), "rb");  // plain files pass through
    std::string text;
    char buffer[1 << 14];
    int n = 0;
    while ((n = gzread(gz, buffer, sizeof buffer)) > 0)
      text.append(buffer, static_cast<std::size_t>(n));
    gzclose(gz);
    std::vector<std::string> lines;
    std::stringstream split(text);
    for (std::string line; std::getline(split, line);) lines.push_back(line);
    return lines;
  };
  const std::vector<std::string> recorded_lines = damaged_lines_of(recording),
                                 paper_lines = damaged_lines_of(paper);

  struct Damage {
    const char* what;
    std::function<std::vector<std::string>(std::vector<std::string>)> apply;
    const char* expected;  // the part of the message that says what was expected
  };
  const auto restamp = [](std::vector<std::string> lines, const auto& stamp) {
    for (std::size_t i = 1; i < lines.size(); ++i) {
      const auto comma = lines[i].find(',');
      lines[i] = stamp(std::stoll(lines[i].substr(0, comma))) + lines[i].substr(comma);
    }
    return lines;
  };
  const std::vector<Damage> damages = {
      {"truncated",
       [](std::vector<std::string> l) {
         l.resize(2);
         return l;
       },
       "expected at least 2 data rows"},
      {"wrong header",
       [](std::vector<std::string> l) {
         l[0] = std::regex_replace(l[0], std::regex(",Speed,"), ",Velocity,");
         return l;
       },
       "missing column 'Speed'"},
      {"stamps in microseconds",
       [&](std::vector<std::string> l) {
         return restamp(l, [](long long ms) { return std::to_string(ms * 1000); });
       },
       "expected frames at most 50 ms apart"},
      {"stamps in seconds",
       [&](std::vector<std::string> l) {
         return restamp(l, [](long long ms) {
           return std::to_string(ms / 1000) + "." + std::to_string(1000 + ms % 1000).substr(1);
         });
       },
       "field 'Unix Timestamp': expected a whole number"},
  };
  std::filesystem::create_directories(out / "damaged");
  const auto refusal = [&](const std::vector<std::string>& lines, const std::filesystem::path& file,
                           const char* expected) {
    {
      std::ofstream o(file);
      for (const auto& line : lines) o << line << '\n';
    }
    ::testing::internal::CaptureStderr();
    const int code = run_cli({"render", "--tool", "cryon", "--surface", "office", "--trajectory",
                              file.string(), "-o", (out / "never.wav").string()});
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(code, 1) << err;
    EXPECT_FALSE(std::filesystem::exists(out / "never.wav"));
    EXPECT_NE(err.find(file.string()), std::string::npos) << "names the file: " << err;
    EXPECT_NE(err.find(expected), std::string::npos) << err;
    // What differs between the two files: their names, and the values quoted from them.
    std::string general = err;
    general.replace(general.find(file.string()), file.string().size(), "FILE");
    return std::regex_replace(general, std::regex("'[^']*'"), "V");
  };
  for (const Damage& damage : damages) {
    SCOPED_TRACE(damage.what);
    const std::string from_recording = refusal(
        damage.apply(recorded_lines), out / "damaged" / "pen_tablet_damaged.csv", damage.expected);
    const std::string from_paper = refusal(
        damage.apply(paper_lines), out / "damaged" / "charc_paper_ball.csv", damage.expected);
    EXPECT_EQ(from_recording, from_paper);
  }
}

}  // namespace
}  // namespace nibrig::ui::cli
