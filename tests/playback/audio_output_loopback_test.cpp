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

// How the recorder's cycles line up with the renderer's calls on the server's frame clock.
struct CycleCheck {
  std::size_t cycles = 0;   // recorded cycles
  std::size_t on_time = 0;  // equal to the block rendered in the same cycle (delay 0)
  std::size_t shifted = 0;  // equal to a block rendered a few cycles earlier or later
  std::size_t torn = 0;     // each sample from one of the nearby blocks: read during a write
  std::size_t silent = 0;   // all zero: JACK's silence for a client that missed the cycle
  std::size_t altered = 0;  // some sample from no nearby block: a sample was changed
  std::size_t exact = 0;    // of the matching cycles, bit-identical ones
};

double block_error(const std::vector<float>& recorded, std::size_t at,
                   const std::vector<float>& rendered, std::size_t from, std::size_t frames) {
  double worst = 0.0;
  for (std::size_t i = 0; i < frames; ++i) {
    worst = std::max(worst, std::abs(double{recorded[at + i]} - double{rendered[from + i]}));
  }
  return worst;
}

// Compares each recorded cycle with the block the renderer produced in the cycle that started at
// the same frame time, and, when that fails, with the blocks of the 8 calls either side.
CycleCheck check_cycles(const JackRecorder& ear, std::size_t input,
                        const SignalRenderer& renderer) {
  const std::size_t calls = renderer.calls();
  const std::vector<float> offline = render_offline(calls * kPeriod, kPeriod);
  std::vector<jack_nframes_t> call_times(calls);
  for (std::size_t c = 0; c < calls; ++c) call_times[c] = renderer.call_time(c);
  const std::vector<float>& recorded = ear.samples(input);

  CycleCheck check;
  for (const JackRecorder::Cycle& cycle : ear.cycles()) {
    ++check.cycles;
    const auto at = std::lower_bound(call_times.begin(), call_times.end(), cycle.time);
    const auto same = static_cast<std::size_t>(at - call_times.begin());
    auto matches = [&](std::size_t call) {
      const double error =
          block_error(recorded, cycle.start, offline, call * kPeriod, cycle.frames);
      check.exact += error == 0.0 ? 1 : 0;
      return error <= kTolerance;
    };
    if (same < calls && call_times[same] == cycle.time && matches(same)) {
      ++check.on_time;
      continue;
    }
    const std::size_t first = same > 8 ? same - 8 : 0;
    const std::size_t last = std::min(calls, same + 9);
    bool found = false;
    for (std::size_t c = first; c < last && !found; ++c) found = c != same && matches(c);
    if (found) {
      ++check.shifted;
      continue;
    }
    if (std::all_of(recorded.begin() + cycle.start, recorded.begin() + cycle.start + cycle.frames,
                    [](float x) { return x == 0.0f; })) {
      ++check.silent;
      continue;
    }
    bool every_sample_rendered = true;
    for (std::size_t i = 0; i < cycle.frames && every_sample_rendered; ++i) {
      bool seen = false;
      for (std::size_t c = first; c < last && !seen; ++c) {
        seen = std::abs(double{recorded[cycle.start + i]} - double{offline[c * kPeriod + i]}) <=
               kTolerance;
      }
      every_sample_rendered = seen;
    }
    ++(every_sample_rendered ? check.torn : check.altered);
  }
  return check;
}

void expect_played_as_rendered(const CycleCheck& c, const JackRecorder& ear,
                               const AudioOutput& output) {
  SCOPED_TRACE(::testing::Message()
               << c.cycles << " cycles: " << c.on_time << " on time, " << c.shifted << " shifted, "
               << c.altered << " altered; " << ear.xruns() << " xruns seen by the recorder, "
               << output.stats().output_underflows << " by the stream");
  ::testing::Test::RecordProperty("cycles", std::to_string(c.cycles));
  ::testing::Test::RecordProperty("cycles_on_time", std::to_string(c.on_time));
  ::testing::Test::RecordProperty("cycles_shifted", std::to_string(c.shifted));
  ::testing::Test::RecordProperty("cycles_torn", std::to_string(c.torn));
  ::testing::Test::RecordProperty("cycles_silent", std::to_string(c.silent));
  EXPECT_GT(c.cycles, 0u);
  // No sample may be one the renderer did not produce at that place in a nearby cycle (JACK hands
  // one output to one input unchanged).
  EXPECT_EQ(c.altered, 0u);
  EXPECT_EQ(c.exact, c.on_time + c.shifted) << "matches within the tolerance but not bit-exact";
  // Delay 0: a downstream client runs after its upstream one in the same cycle, and RtAudio
  // writes its ports right after the callback, so the recorder gets a block the cycle it was
  // rendered. The test server runs without realtime priority on a shared 2-core machine: a late
  // client is an xrun, after which JACK (asynchronous mode) may hand a block a cycle late, while
  // it is being written, or silence in its place. Allow that for at most 10% of the cycles, and
  // only when JACK reported xruns.
  EXPECT_GE(c.on_time * 10, c.cycles * 9);
  if (c.shifted + c.torn + c.silent > 0) {
    EXPECT_GT(ear.xruns() + output.stats().output_underflows, 0u);
  }
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

  expect_played_as_rendered(check_cycles(ear, 0, renderer), ear, output);
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
  expect_played_as_rendered(check_cycles(ear, 1, renderer), ear, output);
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
