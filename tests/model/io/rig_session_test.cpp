#include "model/io/rig_session.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sndfile.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "model/io/rig_session_json.hpp"
#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

RigSessionInfo rig_info() {
  RigSessionInfo info;
  info.tool = "p2h";
  info.surface = "office";
  info.normal_load_N = 2.2;
  info.acceleration_rate_hz = 48000;
  info.speed_rate_hz = 1000;
  info.force_rate_hz = 500;
  info.units = {{"acceleration", "audio full scale"},
                {"speed", "m/s"},
                {"normal_force", "N"},
                {"tangential_force", "N"}};
  info.calibration.accelerometer_m_s2_per_unit = 49.05;
  info.calibration.force_counts_per_N = 403.2;
  info.calibration.lever_factor = 14.0;
  info.speed_profile = "sweep 17-250 mm/s, 3 s period";
  info.notes = "test";
  return info;
}

// Sample k of a stream: distinct in every stream and block, so any lost or reordered block shows.
float sample(int stream, std::size_t k) {
  return static_cast<float>(stream) +
         static_cast<float>(std::sin(0.001 * static_cast<double>(k))) * 0.5f;
}

std::vector<float> block(int stream, std::size_t block_index, std::size_t size) {
  std::vector<float> samples(size);
  for (std::size_t i = 0; i < size; ++i) samples[i] = sample(stream, block_index * size + i);
  return samples;
}

constexpr std::size_t kAccelBlock = 480;  // 10 ms at 48 kHz
constexpr std::size_t kSlowBlock = 10;    // 10 ms at 1 kHz (speed), 20 ms at 500 Hz (forces)

void write_blocks(RigSessionWriter& writer, std::size_t index) {
  writer.append_acceleration(block(0, index, kAccelBlock));
  writer.append_speed(block(1, index, kSlowBlock));
  writer.append_normal_force(block(2, index, kSlowBlock));
  writer.append_tangential_force(block(3, index, kSlowBlock));
}

void expect_stream(const std::vector<float>& samples, int stream, std::size_t block_size,
                   std::size_t at_least_blocks) {
  EXPECT_GE(samples.size(), at_least_blocks * block_size) << "stream " << stream;
  EXPECT_EQ(samples.size() % block_size, 0u) << "stream " << stream << " holds part of a block";
  for (std::size_t k = 0; k < samples.size(); ++k) {
    ASSERT_EQ(samples[k], sample(stream, k)) << "stream " << stream << " sample " << k;
  }
}

// The byte count in a WAV file's "data" chunk header, found by walking the RIFF chunks. Read by
// hand rather than through libsndfile, to show the header itself is up to date (any WAV reader
// would see the data), not only that libsndfile can cope with a stale one.
std::uint32_t wav_data_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  char riff[12];
  in.read(riff, sizeof riff);
  EXPECT_EQ(std::string(riff, 4), "RIFF");
  for (;;) {
    char id[4];
    std::uint32_t size = 0;
    in.read(id, 4);
    in.read(reinterpret_cast<char*>(&size), 4);  // little-endian, as is the host
    if (!in) {
      ADD_FAILURE() << file << " has no data chunk";
      return 0;
    }
    if (std::string(id, 4) == "data") return size;
    in.seekg(size + (size & 1), std::ios::cur);
  }
}

TEST(RigSession, WriteFinishReadRoundTrip) {
  const auto dir = nibrig::test::scratch_dir("session_round_trip");
  const auto folder = dir / "p2h_office";
  {
    RigSessionWriter writer(folder, rig_info());
    EXPECT_TRUE(std::filesystem::is_directory(dir / "p2h_office.partial"));
    for (std::size_t b = 0; b < 25; ++b) write_blocks(writer, b);
    writer.finish();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "p2h_office.partial"));
  const RigSession session = read_rig_session(folder);
  EXPECT_TRUE(session.complete);
  EXPECT_TRUE(session.warnings.empty());
  EXPECT_EQ(session.info.tool, "p2h");
  EXPECT_EQ(session.info.units, rig_info().units);
  EXPECT_EQ(session.info.speed_profile, "sweep 17-250 mm/s, 3 s period");
  EXPECT_EQ(session.info.calibration.lever_factor, 14.0);
  EXPECT_EQ(session.info.force_rate_hz, 500.0);
  EXPECT_FALSE(session.info.created_utc.empty());  // filled in by the writer
  ASSERT_EQ(session.acceleration.size(), 25 * kAccelBlock);
  ASSERT_EQ(session.tangential_force_N.size(), 25 * kSlowBlock);
  expect_stream(session.acceleration, 0, kAccelBlock, 25);
  expect_stream(session.speed_m_s, 1, kSlowBlock, 25);
  expect_stream(session.normal_force_N, 2, kSlowBlock, 25);
  expect_stream(session.tangential_force_N, 3, kSlowBlock, 25);
}

// A capture keeps its record current while recording: a .partial folder says how far it got, and the
// finished session keeps the last record. A session without one reads with none.
TEST(RigSession, CaptureRecordIsKeptCurrentAndReadBack) {
  const auto dir = nibrig::test::scratch_dir("session_capture_record");
  const auto folder = dir / "rig";
  CaptureRecord record;
  record.rig = "simulated rig, seed 3";
  record.seconds = 0.25;
  record.frames = 250;
  record.dropped_frames = 2;
  record.saturated_frames = 7;
  record.fault_frames = 1;
  record.alignment_error_ms = 0.125;
  {
    RigSessionWriter writer(folder, rig_info());
    for (std::size_t b = 0; b < 3; ++b) write_blocks(writer, b);
    writer.update_capture(record);
    const RigSession partial = read_rig_session(dir / "rig.partial");
    ASSERT_TRUE(partial.info.capture.has_value());
    EXPECT_EQ(partial.info.capture->frames, 250u);
    EXPECT_EQ(partial.info.capture->ended_because, "");  // still recording when it was written
    record.ended_because = "profile finished";
    record.frames = 300;
    writer.update_capture(record);
    writer.finish();
    EXPECT_THROW(writer.update_capture(record), std::logic_error);
  }
  const RigSession session = read_rig_session(folder);
  ASSERT_TRUE(session.info.capture.has_value());
  const CaptureRecord& read = *session.info.capture;
  EXPECT_EQ(read.rig, "simulated rig, seed 3");
  EXPECT_EQ(read.seconds, 0.25);
  EXPECT_EQ(read.frames, 300u);
  EXPECT_EQ(read.dropped_frames, 2u);
  EXPECT_EQ(read.saturated_frames, 7u);
  EXPECT_EQ(read.fault_frames, 1u);
  EXPECT_EQ(read.alignment_error_ms, 0.125);
  EXPECT_EQ(read.ended_because, "profile finished");

  const auto plain = dir / "plain";
  {
    RigSessionWriter writer(plain, rig_info());
    write_blocks(writer, 0);
    writer.finish();
  }
  EXPECT_FALSE(read_rig_session(plain).info.capture.has_value());
}

// The real thing: a capture process killed with SIGKILL while it writes. Everything it reported as
// written before the kill must be readable from the .partial folder, with no partial block.
TEST(RigSession, KilledCaptureKeepsEveryBlockWrittenBeforeTheKill) {
  const auto dir = nibrig::test::scratch_dir("session_killed");
  const auto folder = dir / "killed";
  constexpr int kReportedBlocks = 40;
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(pipe_fds[0]);
    try {
      RigSessionWriter writer(folder, rig_info());
      // Keeps writing until killed; reports each finished block.
      for (std::size_t b = 0;; ++b) {
        write_blocks(writer, b);
        const char done = 1;
        if (::write(pipe_fds[1], &done, 1) != 1) ::_exit(3);
      }
    } catch (...) {
      ::_exit(2);
    }
  }
  ::close(pipe_fds[1]);
  int reported = 0;
  char done = 0;
  while (reported < kReportedBlocks && ::read(pipe_fds[0], &done, 1) == 1) ++reported;
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ::close(pipe_fds[0]);
  ASSERT_EQ(reported, kReportedBlocks) << "the capture process failed before the kill";
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);

  EXPECT_FALSE(std::filesystem::exists(folder));
  const RigSession session = read_rig_session(partial_folder_of(folder));
  EXPECT_FALSE(session.complete);
  EXPECT_EQ(session.info.tool, "p2h");
  expect_stream(session.acceleration, 0, kAccelBlock, kReportedBlocks);
  expect_stream(session.speed_m_s, 1, kSlowBlock, kReportedBlocks);
  expect_stream(session.normal_force_N, 2, kSlowBlock, kReportedBlocks);
  expect_stream(session.tangential_force_N, 3, kSlowBlock, kReportedBlocks);
  EXPECT_GE(wav_data_bytes(partial_folder_of(folder) / "acceleration.wav"),
            kReportedBlocks * kAccelBlock * sizeof(float));
  EXPECT_GE(wav_data_bytes(partial_folder_of(folder) / "speed.wav"),
            kReportedBlocks * kSlowBlock * sizeof(float));

  // Reading the finished name points at what the interrupted capture left.
  expect_message_names(format_error_of([&] { read_rig_session(folder); }),
                       {"killed", "no session folder", "killed.partial"});
}

TEST(RigSession, WriterWithoutFinishLeavesAReadablePartialFolder) {
  const auto dir = nibrig::test::scratch_dir("session_unfinished");
  {
    RigSessionWriter writer(dir / "s", rig_info());
    for (std::size_t b = 0; b < 3; ++b) write_blocks(writer, b);
  }
  const RigSession session = read_rig_session(dir / "s.partial");
  EXPECT_FALSE(session.complete);
  expect_stream(session.acceleration, 0, kAccelBlock, 3);
  EXPECT_EQ(session.acceleration.size(), 3 * kAccelBlock);
}

TEST(RigSession, FinishNeverReplacesAnExistingFolder) {
  const auto dir = nibrig::test::scratch_dir("session_existing");
  RigSessionWriter writer(dir / "s", rig_info());
  write_blocks(writer, 0);
  std::filesystem::create_directory(dir / "s");  // appeared while recording (even empty)
  try {
    writer.finish();
    FAIL() << "finish() replaced an existing folder";
  } catch (const std::runtime_error& error) {
    expect_message_names(error.what(), {"already exists", "s.partial"});
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir / "s"));
  EXPECT_EQ(read_rig_session(dir / "s.partial").acceleration.size(), kAccelBlock);
}

TEST(RigSession, WriterRefusesBadInfoExistingFoldersAndBadSamples) {
  const auto dir = nibrig::test::scratch_dir("session_refusals");
  RigSessionInfo fractional_rate = rig_info();
  fractional_rate.speed_rate_hz = 999.5;
  EXPECT_THROW(RigSessionWriter(dir / "a", fractional_rate), std::invalid_argument);
  RigSessionInfo no_tool = rig_info();
  no_tool.tool.clear();
  EXPECT_THROW(RigSessionWriter(dir / "a", no_tool), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir / "a.partial"));

  std::filesystem::create_directory(dir / "taken");
  EXPECT_THROW(RigSessionWriter(dir / "taken", rig_info()), std::runtime_error);
  std::filesystem::create_directory(dir / "left.partial");
  EXPECT_THROW(RigSessionWriter(dir / "left", rig_info()), std::runtime_error);

  RigSessionWriter writer(dir / "b", rig_info());
  const std::vector<float> with_nan = {0.1f, std::numeric_limits<float>::quiet_NaN()};
  EXPECT_THROW(writer.append_speed(with_nan), std::invalid_argument);
  writer.finish();
  EXPECT_THROW(writer.append_speed(std::vector<float>{0.1f}), std::logic_error);
  EXPECT_TRUE(read_rig_session(dir / "b").speed_m_s.empty());  // the NaN block was not written
}

// Malformed sessions: start from a valid finished one and break one thing.
class SessionMalformed : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = nibrig::test::scratch_dir("session_malformed");
    folder_ = dir_ / "s";
    RigSessionWriter writer(folder_, rig_info());
    for (std::size_t b = 0; b < 4; ++b) write_blocks(writer, b);
    writer.finish();
    std::ifstream in(folder_ / "session.json");
    original_ = nlohmann::json::parse(in);
  }
  nlohmann::json json() const { return original_; }
  void set_json(const nlohmann::json& json) const {
    nibrig::test::write_text(folder_ / "session.json", json.dump(2));
  }
  void write_wav(const char* name, int format, int rate, const std::vector<float>& samples) const {
    SF_INFO info{};
    info.samplerate = rate;
    info.channels = 1;
    info.format = format;
    SNDFILE* file = sf_open((folder_ / name).c_str(), SFM_WRITE, &info);
    ASSERT_NE(file, nullptr) << sf_strerror(nullptr);
    sf_write_float(file, samples.data(), static_cast<sf_count_t>(samples.size()));
    sf_close(file);
  }
  std::filesystem::path dir_, folder_;
  nlohmann::json original_;
};

TEST_F(SessionMalformed, MissingSessionJson) {
  std::filesystem::remove(folder_ / "session.json");
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"session.json", "missing", "expected the session description"});
}

TEST_F(SessionMalformed, EmptySessionJson) {
  nibrig::test::write_text(folder_ / "session.json", "");
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"session.json", "empty file", "expected a JSON object"});
}

TEST_F(SessionMalformed, BadJsonSyntaxNamesTheLine) {
  nibrig::test::write_text(folder_ / "session.json",
                   "{\n  \"format\": \"nibrig-session\",\n  \"tool\": ,\n}\n");
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"session.json", "line 3", "invalid JSON"});
}

TEST_F(SessionMalformed, BadFieldIsNamed) {
  auto j = json();
  j["speed_rate_hz"] = "fast";
  set_json(j);
  expect_message_names(
      format_error_of([&] { read_rig_session(folder_); }),
      {"session.json", "field 'speed_rate_hz'", "expected a number, found the string 'fast'"});
  j = json();
  j["calibration"].erase("lever_factor");
  set_json(j);
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"session.json", "field 'calibration.lever_factor'", "missing field"});
  j = json();
  j["force_rate_hz"] = 0;
  set_json(j);
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"field 'force_rate_hz'", "expected a whole number of hertz"});
}

// Issue 46: a positive 1e-320 passed as an accelerometer scale, and the analysis then met every
// sample as a subnormal nothing. The scale is held to the range a rig's request is (--accelerometer,
// 0.01 to 1e6 m/s² at full scale), by the reader and the writer alike.
TEST_F(SessionMalformed, AccelerometerScaleOutsideTheRigsRange) {
  for (const double scale : {1e-320, 1e-3, 1e7}) {
    auto j = json();
    j["calibration"]["accelerometer_m_s2_per_unit"] = scale;
    set_json(j);
    expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                         {"session.json", "field 'calibration.accelerometer_m_s2_per_unit'",
                          "expected an accelerometer's m/s² at full scale, 0.01 to 1e+06"});
  }
  for (const double scale : {session_json::kLeastAccelerometerM_s2PerUnit, 49.05,
                             session_json::kMostAccelerometerM_s2PerUnit}) {
    auto j = json();
    j["calibration"]["accelerometer_m_s2_per_unit"] = scale;
    set_json(j);
    EXPECT_EQ(read_rig_session(folder_).info.calibration.accelerometer_m_s2_per_unit, scale);
  }
  RigSessionInfo tiny = rig_info();
  tiny.calibration.accelerometer_m_s2_per_unit = 1e-320;
  EXPECT_THROW(RigSessionWriter(dir_ / "tiny", tiny), std::invalid_argument);
}

// A load of 1e-320 N was divided into the tangential force; 0 (a session not about friction) and
// the friction reader's range are what a session may say.
TEST_F(SessionMalformed, ALoadOutsideTheFrictionRangeIsNamed) {
  for (const double load : {1e-320, 0.005, 51.0}) {
    auto j = json();
    j["normal_load_N"] = load;
    set_json(j);
    expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                         {"session.json", "field 'normal_load_N'", "expected a load in newtons, 0 or 0.01 to 50"});
  }
  for (const double load : {0.0, 0.01, 2.2, 50.0}) {
    auto j = json();
    j["normal_load_N"] = load;
    set_json(j);
    EXPECT_EQ(read_rig_session(folder_).info.normal_load_N, load);
  }
}

TEST_F(SessionMalformed, WrongSampleRate) {
  auto j = json();
  j["speed_rate_hz"] = 2000;
  set_json(j);
  expect_message_names(
      format_error_of([&] { read_rig_session(folder_); }),
      {"speed.wav", "header", "wrong sample rate: expected 2000 Hz (session.json), found 1000 Hz"});
}

TEST_F(SessionMalformed, NonFloatWav) {
  write_wav("normal_force.wav", SF_FORMAT_WAV | SF_FORMAT_PCM_16, 500, block(2, 0, 40));
  expect_message_names(
      format_error_of([&] { read_rig_session(folder_); }),
      {"normal_force.wav", "header", "expected 32-bit float samples, found 16-bit integer"});
}

TEST_F(SessionMalformed, NaNSamples) {
  std::vector<float> samples = block(3, 0, 40);
  samples[17] = std::numeric_limits<float>::quiet_NaN();
  write_wav("tangential_force.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 500, samples);
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"tangential_force.wav", "sample 17", "expected a finite value, found NaN"});
}

TEST_F(SessionMalformed, StereoWav) {
  SF_INFO info{};
  info.samplerate = 1000;
  info.channels = 2;
  info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
  SNDFILE* file = sf_open((folder_ / "speed.wav").c_str(), SFM_WRITE, &info);
  ASSERT_NE(file, nullptr);
  sf_close(file);
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"speed.wav", "expected 1 channel, found 2"});
}

TEST_F(SessionMalformed, FrameCountDiffersFromSessionJson) {
  write_wav("speed.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 1000, block(1, 0, 30));
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"speed.wav", "expected 40 frames (session.json), found 30"});
}

TEST_F(SessionMalformed, MissingOrGarbageStream) {
  std::filesystem::remove(folder_ / "acceleration.wav");
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"acceleration.wav", "missing", "expected a mono float32 WAV stream"});
  nibrig::test::write_text(folder_ / "acceleration.wav", "RIFF nonsense");
  expect_message_names(format_error_of([&] { read_rig_session(folder_); }),
                       {"acceleration.wav", "expected a WAV file"});
}

}  // namespace
}  // namespace nibrig::model::io
