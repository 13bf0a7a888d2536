#include "model/io/acceleration_trace.hpp"

#include <gtest/gtest.h>
#include <sndfile.h>

#include <cmath>
#include <vector>

#include "model/io/format_error.hpp"
#include "model/io/rig_session.hpp"
#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

AccelerationTrace decaying_sine(std::size_t samples) {
  AccelerationTrace trace{2000.0, {}};
  for (std::size_t i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / trace.sample_rate_hz;
    trace.acceleration_m_s2.push_back(3.0 * std::exp(-2 * t) * std::sin(2 * M_PI * 37 * t));
  }
  return trace;
}

TEST(AccelerationTrace, CsvRoundTripKeepsRateAndSamples) {
  const auto file = nibrig::test::scratch_dir("trace") / "ring.csv";
  const AccelerationTrace written = decaying_sine(500);
  write_acceleration_trace(file, written);
  const AccelerationTrace read = read_acceleration_trace(file);
  // Times are written with 10 significant digits: the rate comes back to that precision.
  EXPECT_NEAR(read.sample_rate_hz, 2000.0, 1e-6);
  ASSERT_EQ(read.acceleration_m_s2.size(), 500u);
  for (std::size_t i = 0; i < 500; ++i)
    EXPECT_NEAR(read.acceleration_m_s2[i], written.acceleration_m_s2[i], 1e-9);
}

TEST(AccelerationTrace, SessionFolderGivesCalibratedAcceleration) {
  const auto folder = nibrig::test::scratch_dir("trace_session") / "ring";
  RigSessionInfo info;
  info.tool = "bar";
  info.surface = "none";
  info.normal_load_N = 0.0;
  info.acceleration_rate_hz = 4000;
  info.speed_rate_hz = 100;
  info.force_rate_hz = 100;
  info.calibration.accelerometer_m_s2_per_unit = 9.80665 * 16;  // a ±16 g sensor at full scale
  {
    RigSessionWriter writer(folder, info);
    std::vector<float> samples(400, 0.25f);
    writer.append_acceleration(samples);
    writer.finish();
  }
  const AccelerationTrace trace = read_acceleration_trace(folder);
  EXPECT_DOUBLE_EQ(trace.sample_rate_hz, 4000);
  ASSERT_EQ(trace.acceleration_m_s2.size(), 400u);
  EXPECT_NEAR(trace.acceleration_m_s2[0], 0.25 * 9.80665 * 16, 1e-9);
}

TEST(AccelerationTrace, BadFilesNameFileLineAndExpectation) {
  const auto dir = nibrig::test::scratch_dir("trace_bad");
  std::string rows;
  for (int i = 0; i < 20; ++i) rows += std::to_string(i * 0.001) + ",0.5\n";

  nibrig::test::write_text(dir / "uneven.csv", "time_s,acceleration_m_s2\n" + rows + "0.025,0.5\n");
  expect_message_names(format_error_of([&] { read_acceleration_trace(dir / "uneven.csv"); }),
                       {"uneven.csv", "line 22", "evenly spaced"});

  nibrig::test::write_text(dir / "nan.csv", "time_s,acceleration_m_s2\n0,0.1\n0.001,nan\n" + rows);
  expect_message_names(format_error_of([&] { read_acceleration_trace(dir / "nan.csv"); }),
                       {"nan.csv", "line 3", "acceleration_m_s2"});

  nibrig::test::write_text(dir / "column.csv", "time_s,accel_g\n" + rows);
  expect_message_names(format_error_of([&] { read_acceleration_trace(dir / "column.csv"); }),
                       {"column.csv", "acceleration_m_s2"});

  nibrig::test::write_text(dir / "short.csv", "time_s,acceleration_m_s2\n0,1\n0.001,2\n");
  expect_message_names(format_error_of([&] { read_acceleration_trace(dir / "short.csv"); }),
                       {"short.csv", "at least 16 samples"});

  nibrig::test::write_text(dir / "backwards.csv",
                   "time_s,acceleration_m_s2\n0,1\n0.002,2\n0.001,2\n" + rows);
  expect_message_names(format_error_of([&] { read_acceleration_trace(dir / "backwards.csv"); }),
                       {"backwards.csv", "line 4", "increase"});

  nibrig::test::write_text(dir / "empty.csv", "");
  expect_message_names(format_error_of([&] { read_acceleration_trace(dir / "empty.csv"); }),
                       {"empty.csv", "time_s,acceleration_m_s2"});
}

// A WAV as an audio interface records it: 16-bit PCM at 8 kHz.
void write_pcm16_wav(const std::filesystem::path& file, int channels, const std::vector<short>& frames) {
  SF_INFO info{};
  info.samplerate = 8000;
  info.channels = channels;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  SNDFILE* out = sf_open(file.c_str(), SFM_WRITE, &info);
  ASSERT_NE(out, nullptr) << sf_strerror(nullptr);
  sf_write_short(out, frames.data(), static_cast<sf_count_t>(frames.size()));
  sf_close(out);
}

TEST(AccelerationTrace, AnAudioInputsMonoWavIsReadInFullScaleUnits) {
  const auto dir = nibrig::test::scratch_dir("acceleration_trace_wav");
  std::vector<short> samples(400);
  for (std::size_t i = 0; i < samples.size(); ++i)
    samples[i] = static_cast<short>(std::lround(16384 * std::sin(0.05 * static_cast<double>(i))));
  write_pcm16_wav(dir / "ring.WAV", 1, samples);
  const AccelerationTrace trace = read_acceleration_trace(dir / "ring.WAV");
  EXPECT_EQ(trace.sample_rate_hz, 8000.0);  // the header's whole number, exactly
  ASSERT_EQ(trace.acceleration_m_s2.size(), samples.size());
  // libsndfile scales 16-bit integers by 1/32768: exact in a double.
  for (std::size_t i = 0; i < samples.size(); ++i)
    EXPECT_EQ(trace.acceleration_m_s2[i], samples[i] / 32768.0) << i;

  // A stereo recording is refused: which channel is the accelerometer's is for a person to say.
  write_pcm16_wav(dir / "stereo.wav", 2, std::vector<short>(800, 100));
  try {
    read_acceleration_trace(dir / "stereo.wav");
    FAIL() << "a stereo WAV was read";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("stereo.wav"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected 1 channel"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::model::io
