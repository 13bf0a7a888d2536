// The design view on a real JACK server: dragging the mix slider from VeroClear to DM85 changes
// what the actuator receives within 50 ms. An independent libjack client records the panel's output
// as it goes. The two designs play at nearly one level (within about 1 dB), so the change is found
// by what is played, not how loud: the old design's voice is deterministic (its seed, a constant
// stroke), so an offline render of it lines up with the recording sample for sample until the
// voice is swapped out. The recording is read in 10 ms windows for the first from which the old
// voice is gone for good, and then sample by sample, against the render at the last window's
// alignment, for where it first departs from it: the start of the swap's crossfade.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <thread>

#include "model/design/tool_sound.hpp"
#include "playback/prepared_engine.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/support/jack_server.hpp"
#include "tests/ui/panel/design_cache.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel {
namespace {

using namespace std::chrono_literals;

// A design's sound as the panel plays it (slot 0, the audition's first seed, 100 mm/s and 2.2 N),
// rendered offline from the voice's start for `seconds`.
std::vector<float> offline(const model::design::PredictedTool& tool, double seconds) {
  const auto sound = model::design::predicted_sound(tool);
  playback::PreparedEngine session(rt::EngineSettings{}, sound,
                                   std::make_unique<rt::ConstantStroke>(0.1, 2.2), 1);
  std::vector<float> out(static_cast<std::size_t>(seconds * 48000.0) / 64 * 64);
  for (std::size_t at = 0; at < out.size(); at += 64) session.engine().render(out.data() + at, 64);
  return out;
}

// Normalised correlation of a[0..n) with b[0..n).
double correlation(const float* a, const float* b, std::size_t n) {
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (std::size_t i = 0; i < n; ++i) ab += double(a[i]) * b[i], aa += double(a[i]) * a[i], bb += double(b[i]) * b[i];
  return aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 0.0;
}

TEST(DesignPlayback, DraggingTheMixSliderChangesTheSignalWithinFiftyMilliseconds) {
  nibrig::testing::JackServer server;
  const PanelSetup setup = testing::jack_design_setup("panel_design_playback");
  PanelWindow window(testing::hidden_window());
  Panel panel(setup);
  panel.audio().stroke() = StrokeChoice{0, 100.0f, 2.2f, {}};  // the offline render's constant stroke
  panel.audio().stroke_changed();
  panel.show(View::design);
  auto& view = panel.design_view();
  const auto frame = [&](const std::function<void(ImGuiIO&)>& input = {}) {
    window.begin_frame(input);
    panel.draw();
    window.end_frame();
  };
  const auto deadline = std::chrono::steady_clock::now() + 900s;
  // After the cache is built, as the 50 ms budget assumes, and with the grid's error against the
  // FEM measured: its background solve would otherwise share the two cores with the measurement.
  testing::draw_until_design_settled(panel, [&] { frame(); }, deadline);
  ASSERT_TRUE(view.ready()) << view.error() << " " << panel.error();
  view.set_target(2);
  view.set_design(0.0, 2.5);  // VeroClear, playing at a constant 100 mm/s from here
  ASSERT_TRUE(view.error().empty()) << view.error();
  const auto voice_started = std::chrono::steady_clock::now();

  playback::testing::JackRecorder ear("ear", 1, 96000);  // 2 s
  ASSERT_TRUE(ear.connect("nibrig-panel:outport 0", 0));
  ear.start();
  // Frames at about the pace of a screen's (the hidden window has no vsync): drawn back to back,
  // llvmpipe's threads took both cores and JACK's clients skipped periods every few windows.
  const auto paced_frame = [&] {
    frame();
    std::this_thread::sleep_for(10ms);
  };
  while (ear.recorded() < 48000) paced_frame();  // a second of the old design
  paced_frame();
  const auto slider = view.mix_slider_rect();  // named: clang 14 lambdas cannot capture bindings
  const ImVec2 min = slider.first, max = slider.second;
  const float y = 0.5f * (min.y + max.y);
  frame([&](ImGuiIO& io) { io.MousePos = {min.x + 1.0f, y}; });
  // The press at the slider's left end leaves it where it was (0.00 at the slider's precision): the
  // slider moves on the drag's frame. Where the recording is just before that frame (the
  // recorder's cycles run with the panel's; jack_frame_time's estimate from this thread ran up to
  // 70 ms ahead of them on the dummy driver), then the drag to the right end.
  frame([&](ImGuiIO& io) { io.MousePos = {min.x + 1.0f, y}, io.MouseDown[0] = true; });
  ASSERT_EQ(view.predicted()->point.fraction_of("DM85"), 0.0) << "the press moved the design already";
  const std::size_t at = ear.recorded();
  const auto at_time = std::chrono::steady_clock::now();
  frame([&](ImGuiIO& io) { io.MousePos = {max.x + 5.0f, y}, io.MouseDown[0] = true; });
  frame([&](ImGuiIO& io) { io.MousePos = {max.x + 5.0f, y}, io.MouseDown[0] = false; });
  EXPECT_NEAR(view.predicted()->point.fraction_of("DM85"), 1.0, 1e-9);
  const double update_ms = view.last_update_ms();
  // The panel's part, from the recording's mark to the sound's hand-over: the drag frame's widgets
  // before the slider, the prediction and the voice.
  const double panel_ms = std::chrono::duration<double, std::milli>(view.last_sound_sent() - at_time).count();
  while (ear.recorded() < 96000 && std::chrono::steady_clock::now() < deadline) paced_frame();
  ASSERT_TRUE(ear.wait_full(1s));
  const double played_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - voice_started).count();

  ASSERT_GT(at, 24000u);
  const auto& samples = ear.samples(0);

  // The old voice offline, from its start to past the recording's end; where the recording's
  // samples 100 ms (or a little more) before the move lie in it (the best correlation over every lag).
  view.set_playing(false);
  view.set_design(0.0, 2.5);
  const std::vector<float> reference = offline(*view.predicted(), played_s + 1.0);
  // A glitch (a late callback skipping a period under load) inside the probe leaves no lag that
  // fits it whole: the first of a few probes that fits is taken.
  const std::size_t length = 1024;
  std::size_t probe = 0, lag = 0;
  double best = -1.0;
  for (std::size_t back : {4800u, 7200u, 9600u, 12000u, 14400u}) {
    probe = at - back;
    best = -1.0;
    for (std::size_t k = 0; k + length <= reference.size(); ++k) {
      const double r = correlation(samples.data() + probe, reference.data() + k, length);
      if (r > best) best = r, lag = k;
    }
    if (best > 0.99) break;
  }
  RecordProperty("old_voice_correlation", std::to_string(best));
  ASSERT_GT(best, 0.99) << "the recording does not follow the old design's offline render";
  // The 10 ms window at `from` follows the old voice: it is in the render near where the probe's
  // alignment puts it (within 40 ms: a late callback on a loaded machine skips a period or a few).
  // Its best correlation there, and the render's index that its first sample lines up with.
  struct Fit {
    double correlation = -1.0;
    std::size_t at = 0;
  };
  const auto best_near = [&](std::size_t from) {
    const long expected = static_cast<long>(lag + from) - static_cast<long>(probe);
    Fit fit;
    for (long k = std::max(0L, expected - 1920); k <= expected + 1920; ++k)
      if (static_cast<std::size_t>(k) + 480 <= reference.size()) {
        const double r = correlation(samples.data() + from, reference.data() + k, 480);
        if (r > fit.correlation) fit = {r, static_cast<std::size_t>(k)};
      }
    return fit;
  };
  const auto follows = [&](std::size_t from) { return best_near(from).correlation > 0.9; };
  // After it, the old voice is gone for good: the first window from which none of the next 100 ms
  // follows it (a lone window with a glitch does not count).
  std::optional<std::size_t> gone_from;
  for (std::size_t from = at; from + 480 + 4800 <= samples.size(); from += 48) {
    bool gone = true;
    for (std::size_t later = from; later <= from + 4800 && gone; later += 480) gone = !follows(later);
    if (gone) {
      gone_from = from;
      break;
    }
  }
  ASSERT_TRUE(gone_from.has_value()) << "the recording still follows the old design after the move";
  // Where it departs: from the probe on, sample by sample against the render at the probe's
  // alignment, the first sample from which the recording differs from it by more than a twentieth
  // of the render's level for most of the next millisecond (an equal-power crossfade's new voice
  // reaches that within its first millisecond; before it, the two agree to float rounding). A
  // glitch on the way (a late callback on a loaded machine: the recording jumps ahead in the
  // render, or holds a silent or repeated period) is followed, not taken for the change: where the
  // recording stops following, it counts as departed only if it does not follow the render again,
  // within 40 ms of where it was, in the next 10 ms. So the recording follows the old design from
  // the probe to the departure, and that is after the move.
  double level = 0.0;
  for (std::size_t i = 0; i < length; ++i) level += double(reference[lag + i]) * reference[lag + i];
  const double tolerance = 0.05 * std::sqrt(level / static_cast<double>(length));
  long shift = static_cast<long>(lag) - static_cast<long>(probe);  // render index − recording index
  const auto differs = [&](std::size_t n, long by) {
    const long k = static_cast<long>(n) + by;
    return k < 0 || static_cast<std::size_t>(k) >= reference.size() ||
           std::abs(double(samples[n]) - reference[static_cast<std::size_t>(k)]) > tolerance;
  };
  const auto differing = [&](std::size_t n, long by) {
    std::size_t count = 0;
    for (std::size_t m = n; m < n + 48; ++m) count += differs(m, by);
    return count;
  };
  std::optional<std::size_t> departs;
  std::size_t skips = 0;
  for (std::size_t n = probe; n + 48 < samples.size(); ++n) {
    if (!differs(n, shift) || differing(n, shift) <= 24) continue;
    // Where within the next 10 ms (in steps of 8 samples) it follows the render again, within 40 ms
    // of where it was: a skipped period resumes at once, a late one that left a period silent or
    // repeated resumes a period later; the new voice never does.
    // It follows again only where it keeps following for 5 ms: among ~4000 lags, one that fits 48
    // quiet samples by chance was found (the new voice taken for the old one resumed: the change
    // measured 50 ms late in a third of Release runs); a resumed glitch follows on.
    const auto follows_on = [&](std::size_t m, long by) {
      for (std::size_t k = m; k < m + 240; k += 48)
        if (k + 48 >= samples.size() || differing(k, by) > 2) return false;
      return true;
    };
    std::optional<std::pair<std::size_t, long>> resumed;
    for (std::size_t m = n; m <= n + 480 && m + 48 < samples.size() && !resumed; m += 8)
      for (long d = 0; d <= 1920 && !resumed; ++d)
        for (long by : {shift + d, shift - d})
          if (!resumed && differing(m, by) <= 2 && follows_on(m, by)) resumed = {m, by};
    if (!resumed) {
      departs = n;
      break;
    }
    ++skips;
    n = resumed->first;
    shift = resumed->second;
  }
  ASSERT_TRUE(departs.has_value()) << "the recording never departs from the old design's render";
  EXPECT_GE(*departs, at) << "the recording departs from the old design before the slider moved";
  const double changed_ms = (static_cast<double>(*departs) - static_cast<double>(at)) / 48.0;
  RecordProperty("slider_to_signal_ms", std::to_string(changed_ms));
  RecordProperty("slider_to_placement_and_voice_ms", std::to_string(update_ms));
  RecordProperty("glitches_followed", std::to_string(skips));
  RecordProperty("mark_to_sound_handed_over_ms", std::to_string(panel_ms));
  // The audio's part, from the hand-over to the signal (the voice's way to the audio thread, its
  // crossfade's start, a period or two of JACK): a few milliseconds whatever the build and load.
  // The recording's clock is the dummy driver's, which a loaded machine delays; late cycles make
  // fewer samples than host time passed, so this errs towards passing only by what they lose.
  EXPECT_LT(changed_ms - panel_ms, 15.0) << "slider to signal " << changed_ms << " ms, of which the panel took "
                                         << panel_ms << " ms (the prediction and the voice " << update_ms << " ms)";
  // The 50 ms budget from the drag to the sound holds for the build that plays (Release: the
  // prediction and the voice take a few ms there, BM_DesignGridSliderToVoice). Under the
  // sanitizers they cost several times as much, past the budget on a slow machine: there the
  // audio's part is what is checked.
#if !defined(__SANITIZE_ADDRESS__)
  EXPECT_LT(changed_ms, 50.0);
#endif
}

}  // namespace
}  // namespace nibrig::ui::panel
