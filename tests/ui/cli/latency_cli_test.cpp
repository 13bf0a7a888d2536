// `nibrig latency` as a user runs it, on a private JACK server with its loopback driver (jackd -L):
// RtAudio lists the driver as a device, `loopback`, whose playback ports come back on its capture
// ports a cycle later, so the command connects to it like to a sound card with a cable looped.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/jack_server.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;

TEST(LatencyCliJack, MeasuresTheLoopbackDriversCycleAndRtAudiosPeriod) {
  nibrig::testing::JackServer server({48000, 128, 2});
  const auto json = nibrig::test::scratch_dir("cli_latency") / "latency.json";
  ::testing::internal::CaptureStdout();
  const int code = run_cli({"latency", "--api", "jack", "--device", "loopback", "--impulses", "10",
                            "--interval", "100", "--period", "128", "--json", json.string()});
  const std::string text = ::testing::internal::GetCapturedStdout();
  ASSERT_EQ(code, 0) << text;
  const auto result = test::read_json(json);
  ASSERT_EQ(result.at("periods").size(), 1u) << result.dump(1);
  const auto& row = result["periods"][0];
  EXPECT_EQ(row.at("stream").at("api"), "jack");
  EXPECT_EQ(row.at("stream").at("period_frames"), 128);
  EXPECT_EQ(row.at("played"), 10);
  ASSERT_TRUE(row.at("mean_samples").is_number()) << row.dump();
  const double mean = row["mean_samples"].get<double>();
  const double worst_ms = row.at("worst_ms").get<double>();
  // One cycle in the loopback driver and one period in RtAudio's JACK back end: 256 frames, 5.333
  // ms (round_trip_run_test). An xrun may hand a block a cycle late or spoil it, so with xruns
  // reported one impulse of the ten may be missing or a period later: the mean within 12.8 frames,
  // the worst within one period.
  if (row.at("xruns") == 0) {
    EXPECT_EQ(row.at("found"), 10) << row.dump();
    EXPECT_NEAR(mean, 256.0, 0.05) << row.dump();
    EXPECT_NEAR(worst_ms, 256.0 / 48.0, 0.001) << row.dump();
  } else {
    EXPECT_GE(row.at("found").get<int>(), 9) << row.dump();
    EXPECT_GE(mean, 256.0) << row.dump();
    EXPECT_LE(mean, 256.0 + 12.8) << row.dump();
    EXPECT_LE(worst_ms, 384.0 / 48.0 + 0.001) << row.dump();
  }
  // The same round trip in both units at the stream's 48 kHz; 1e-9 ms allows the arithmetic.
  EXPECT_NEAR(row.at("mean_ms").get<double>(), mean / 48.0, 1e-9) << row.dump();
}

TEST(LatencyCliJack, AnUnknownInputDeviceIsNamedWithTheDevicesThereAre) {
  nibrig::testing::JackServer server({48000, 128, 2});
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"latency", "--api", "jack", "--device", "loopback", "--input-device",
                            "speakers", "--impulses", "2"});
  const std::string text = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, 1) << text;
  EXPECT_NE(text.find("--input-device"), std::string::npos) << text;
  EXPECT_NE(text.find("speakers"), std::string::npos) << text;
  EXPECT_NE(text.find("'loopback'"), std::string::npos) << text;
}

}  // namespace
}  // namespace nibrig::ui::cli
