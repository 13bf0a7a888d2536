// What AudioOutput plays is exactly what the renderer rendered: a bare libjack client records the
// stream's ports on a real JACK server and the recording is compared, sample by sample, with the
// offline render of the same signal. The server's frame clock, read in both callbacks, gives the
// delay between rendering a frame and the recorder receiving it.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "playback/audio_output.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/playback/jack_stream_settings.hpp"
#include "tests/playback/signal_renderer.hpp"
#include "tests/playback/wait_until.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::playback {
namespace {

using namespace std::chrono_literals;
using testing::jack_settings;
using testing::JackRecorder;
using testing::locate;
using testing::render_offline;
using testing::SignalRenderer;

constexpr std::size_t kPeriod = 64;
constexpr std::size_t kRecordFrames = 2 * 48000;  // 2 s
// JACK hands a port's buffer on unchanged when one output feeds one input: what arrives must
// be the rendered float itself. 1e-6 (about 2^-20 of full scale) only allows for a back end that
// would pass samples through a conversion; anything larger is a different sample.
constexpr double kTolerance = 1e-6;

struct Comparison {
  std::size_t offset = 0;  // recorded[k] is rendered frame k + offset
  long delay_frames = 0;   // recorder's clock minus renderer's clock for the same sample
  double max_error = 0.0;
  std::size_t exact = 0;  // samples bit-identical to the offline render
};

// Lines `recorded` up with the offline render and measures the delay on the server's clock.
Comparison compare(const std::vector<float>& recorded, jack_nframes_t recorded_from,
                   const SignalRenderer& renderer) {
  const std::size_t rendered = renderer.calls() * kPeriod;
  const std::vector<float> offline = render_offline(rendered, kPeriod);
  // A 512-sample window from the middle of the recording (its start may precede the connection).
  const std::size_t probe = recorded.size() / 2;
  const auto found = locate(offline, recorded.data() + probe, 512);
  EXPECT_TRUE(found.has_value()) << "the recording does not occur (exactly once) in the render";
  Comparison c;
  if (!found) return c;
  c.offset = *found - probe;
  for (std::size_t k = 0; k < recorded.size(); ++k) {
    const double error = std::abs(double{recorded[k]} - double{offline[k + c.offset]});
    c.max_error = std::max(c.max_error, error);
    c.exact += recorded[k] == offline[k + c.offset] ? 1 : 0;
  }
  // Rendered frame n was written during the call n / period, whose cycle started at call_time.
  const std::size_t frame = c.offset;  // the frame recorded as sample 0
  const jack_nframes_t rendered_at =
      renderer.call_time(frame / kPeriod) + static_cast<jack_nframes_t>(frame % kPeriod);
  c.delay_frames = static_cast<long>(static_cast<std::int32_t>(recorded_from - rendered_at));
  return c;
}

TEST(AudioOutputLoopback, ChannelOneCarriesTheRenderedSamplesExactlyInTheSameJackCycle) {
  nibrig::testing::JackServer server;
  SignalRenderer renderer;
  JackRecorder ear("ear", 2, kRecordFrames);
  renderer.set_clock(ear.client());
  AudioOutput output(renderer, jack_settings("loop-ch1"));
  EXPECT_EQ(output.stream_info().period_frames, kPeriod);
  ASSERT_TRUE(ear.connect("loop-ch1:outport 0", 0));
  ASSERT_TRUE(ear.connect("loop-ch1:outport 1", 1));
  ear.start();
  ASSERT_TRUE(ear.wait_full(10s)) << "recorded " << ear.recorded() << " frames";

  const Comparison c = compare(ear.samples(0), ear.first_frame_time(), renderer);
  EXPECT_LE(c.max_error, kTolerance);
  EXPECT_EQ(c.exact, kRecordFrames);
  // A downstream client runs after its upstream one in the same cycle: RtAudio writes its output
  // ports after the callback returns, so the recorder gets the block the cycle it was rendered.
  EXPECT_EQ(c.delay_frames, 0) << "offset " << c.offset;
  // Channel 2 was opened (both device outputs are) and carries silence.
  const auto& other = ear.samples(1);
  EXPECT_TRUE(std::all_of(other.begin(), other.end(), [](float x) { return x == 0.0f; }));
  const OutputStats stats = output.stats();
  EXPECT_EQ(stats.frames, stats.callbacks * kPeriod);
  RecordProperty("output_underflows", std::to_string(stats.output_underflows));
  RecordProperty("recorder_xruns", std::to_string(ear.xruns()));
}

TEST(AudioOutputLoopback, ChannelTwoCarriesTheSignalAndChannelOneIsSilent) {
  nibrig::testing::JackServer server;
  SignalRenderer renderer;
  JackRecorder ear("ear", 2, kRecordFrames / 2);
  renderer.set_clock(ear.client());
  AudioOutput output(renderer, jack_settings("loop-ch2", 2));
  ASSERT_TRUE(ear.connect("loop-ch2:outport 0", 0));
  ASSERT_TRUE(ear.connect("loop-ch2:outport 1", 1));
  ear.start();
  ASSERT_TRUE(ear.wait_full(10s)) << "recorded " << ear.recorded() << " frames";

  const auto& first = ear.samples(0);
  EXPECT_TRUE(std::all_of(first.begin(), first.end(), [](float x) { return x == 0.0f; }));
  const Comparison c = compare(ear.samples(1), ear.first_frame_time(), renderer);
  EXPECT_LE(c.max_error, kTolerance);
  EXPECT_EQ(c.delay_frames, 0);
}

TEST(AudioOutputLoopback, CapturedInputIsTheRenderedOutputOnePeriodLater) {
  nibrig::testing::JackServer server;
  SignalRenderer renderer;
  OutputSettings settings = jack_settings("loop-cap");
  settings.input_channel = 1;
  AudioOutput output(renderer, settings);
  EXPECT_EQ(output.stream_info().input_channels, 2u);
  JackRecorder patch("patch", 0, 0);
  ASSERT_TRUE(patch.connect_ports("loop-cap:outport 0", "loop-cap:inport 0"));

  // Drain the ring the way a control thread would, for about a second of audio.
  std::vector<float> captured;
  std::vector<float> block(4096);
  const auto drained = testing::wait_until(
      [&] {
        const std::size_t n = output.read_captured(block.data(), block.size());
        captured.insert(captured.end(), block.begin(), block.begin() + n);
        return captured.size() >= 48000;
      },
      10s);
  ASSERT_GE(drained.count(), 0.0) << "captured " << captured.size() << " samples";

  // Captured sample j arrived in the same callback as rendered frame j (both count from the
  // stream's first callback); a loop delay D makes captured[j] == rendered[j - D].
  const std::vector<float> offline = render_offline(renderer.calls() * kPeriod, kPeriod);
  const std::size_t probe = captured.size() - 1024;
  const auto found = locate(offline, captured.data() + probe, 512);
  ASSERT_TRUE(found.has_value());
  const long delay = static_cast<long>(probe) - static_cast<long>(*found);
  // RtAudio's JACK back end copies the input ports after the callback, for the next one: a
  // sample played in cycle c comes back in cycle c + 1, one period, and never more.
  EXPECT_EQ(delay, static_cast<long>(kPeriod));
  const auto first_sound =
      std::find_if(captured.begin(), captured.end(), [](float x) { return x != 0.0f; });
  ASSERT_NE(first_sound, captured.end());
  double max_error = 0.0;
  for (auto j = static_cast<std::size_t>(first_sound - captured.begin()); j < captured.size();
       ++j) {
    max_error = std::max(max_error, std::abs(double{captured[j]} - double{offline[j - delay]}));
  }
  EXPECT_LE(max_error, kTolerance);
  EXPECT_EQ(output.stats().capture_dropped, 0u);
}

}  // namespace
}  // namespace nibrig::playback
