// The engine with real voices (catalog spectra): deterministic output whatever the block sizes,
// click-free switching, live contact without lag beyond a block, a limiter that holds whatever a
// voice does, and no allocation on the audio thread while another thread floods it with updates.
#include "rt/engine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include "rt/voice_builder.hpp"
#include "tests/rt/test_voices.hpp"
#include "tests/support/allocation_counter.hpp"

namespace nibrig::rt {
namespace {

std::vector<float> render(Engine& engine, std::size_t frames, std::size_t block) {
  std::vector<float> out(frames);
  for (std::size_t at = 0; at < frames; at += block)
    engine.render(out.data() + at, std::min(block, frames - at));
  return out;
}

std::unique_ptr<Engine> engine_with(const std::vector<std::string>& tools, std::size_t selected,
                                    std::unique_ptr<StrokeSource> source) {
  auto engine = std::make_unique<Engine>(EngineSettings{});
  for (std::size_t i = 0; i < tools.size(); ++i)
    EXPECT_TRUE(engine->load(i, testing::catalog_voice(tools[i], "note", engine->internal_rate(), 100 + i)));
  EXPECT_TRUE(engine->select(selected));
  EXPECT_TRUE(engine->attach(std::move(source)));
  return engine;
}

double rms(const std::vector<float>& x, std::size_t from, std::size_t to) {
  double sum = 0;
  for (std::size_t i = from; i < to; ++i) sum += double(x[i]) * x[i];
  return std::sqrt(sum / double(to - from));
}

TEST(Engine, RunsTheVoicesAtAnEighthOfTheDeviceRateOrSo) {
  EXPECT_EQ(Engine(EngineSettings{}).internal_rate(), 8000.0);
  EngineSettings cd;
  cd.sample_rate_hz = 44100;
  EXPECT_EQ(Engine(cd).internal_rate(), 7350.0);
  EngineSettings bad;
  bad.slots = 0;
  EXPECT_THROW(Engine{bad}, std::invalid_argument);
}

TEST(Engine, SilentWithoutVoicesOrContact) {
  Engine engine{EngineSettings{}};
  for (float x : render(engine, 4800, 64)) ASSERT_EQ(x, 0.0f);
  ASSERT_TRUE(engine.load(0, testing::catalog_voice("stab", "note", engine.internal_rate(), 1)));
  for (float x : render(engine, 4800, 64)) ASSERT_EQ(x, 0.0f);  // speed 0, force 0: lifted
}

TEST(Engine, OutputDoesNotDependOnTheBlockSizes) {
  auto a = engine_with({"stab", "cryon"}, 0, std::make_unique<SweepStroke>());
  auto b = engine_with({"stab", "cryon"}, 0, std::make_unique<SweepStroke>());
  const auto x = render(*a, 48000, 64);
  std::vector<float> y(48000);
  for (std::size_t at = 0, block = 1; at < y.size(); block = block % 500 + 37) {
    const std::size_t m = std::min(block, y.size() - at);
    b->render(y.data() + at, m);
    at += m;
  }
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(x[i], y[i]) << i;
  EXPECT_GT(rms(x, 24000, 48000), 1e-4);  // and it is not silence
}

TEST(Engine, SwitchingSlotsCrossfadesWithoutAClick) {
  auto engine = engine_with({"stab", "cryon", "vero2"}, 0, std::make_unique<ConstantStroke>(0.11));
  const auto before = render(*engine, 48000, 64);
  ASSERT_TRUE(engine->select(2));
  const auto after = render(*engine, 48000, 64);
  // A click is a step: the largest sample-to-sample change across the switch must stay within
  // what either voice does on its own (steady parts before and after), with 10 % to spare.
  auto max_step = [](const std::vector<float>& x, std::size_t from, std::size_t to) {
    double m = 0;
    for (std::size_t i = from + 1; i < to; ++i) m = std::max(m, std::abs(double(x[i]) - x[i - 1]));
    return m;
  };
  const double steady = std::max(max_step(before, 0, 48000), max_step(after, 4800, 48000));
  EXPECT_LE(max_step(after, 0, 4800), 1.1 * steady);
  // And the switch is complete after the 20 ms crossfade plus the interpolator: the new voice
  // alone from then on. Its level differs from the old one's.
  EXPECT_GT(std::abs(std::log(rms(after, 4800, 48000) / rms(before, 0, 48000))), 0.05);
  EXPECT_EQ(engine->stats().voices, 3u);  // the others keep running, silently
}

// The design view swaps the voice in slot 0 at every slider move, often faster than the
// crossfade: a press, then a drag on the next frame. Neither swap may click.
TEST(Engine, SwappingTheVoiceOfASlotWhilePlayingCrossfadesWithoutAClick) {
  auto engine = engine_with({"stab"}, 0, std::make_unique<ConstantStroke>(0.1));
  const auto before = render(*engine, 48000, 64);
  ASSERT_TRUE(engine->load(0, testing::catalog_voice("cryon", "note", engine->internal_rate(), 7)));
  const auto first = render(*engine, 320, 64);  // 6.7 ms: the press's voice, fading in
  ASSERT_TRUE(engine->load(0, testing::catalog_voice("vero2", "note", engine->internal_rate(), 8)));
  const auto after = render(*engine, 48000, 64);
  std::vector<float> swap(before.end() - 4800, before.end());
  swap.insert(swap.end(), first.begin(), first.end());
  swap.insert(swap.end(), after.begin(), after.begin() + 4800);
  auto max_step = [](const std::vector<float>& x, std::size_t from, std::size_t to) {
    double m = 0;
    for (std::size_t i = from + 1; i < to; ++i) m = std::max(m, std::abs(double(x[i]) - x[i - 1]));
    return m;
  };
  auto peak = [](const std::vector<float>& x, std::size_t from, std::size_t to) {
    double m = 0;
    for (std::size_t i = from; i < to; ++i) m = std::max(m, std::abs(double(x[i])));
    return m;
  };
  const double steady_step = std::max(max_step(before, 0, 48000), max_step(after, 4800, 48000));
  const double steady_peak = std::max(peak(before, 0, 48000), peak(after, 4800, 48000));
  EXPECT_LE(max_step(swap, 0, swap.size()), 1.1 * steady_step);
  EXPECT_LE(peak(swap, 0, swap.size()), 1.1 * steady_peak);
}

TEST(Engine, LiveContactActsWithinOneBlock) {
  Engine engine{EngineSettings{}};
  ASSERT_TRUE(engine.load(0, testing::catalog_voice("cryon", "note", engine.internal_rate(), 3)));
  for (float x : render(engine, 640, 64)) ASSERT_EQ(x, 0.0f);
  ASSERT_TRUE(engine.set_contact(0.15, 2.2));
  // The first block after the update ramps to the new contact: sound within that block (after
  // the interpolator's delay of 23.5 frames).
  std::vector<float> block(64);
  engine.render(block.data(), 64);
  float loudest = 0;
  for (float x : block) loudest = std::max(loudest, std::abs(x));
  EXPECT_GT(loudest, 0.0f);
}

TEST(Engine, LimiterHoldsWhateverTheVoicesDo) {
  EngineSettings settings;
  Engine engine{settings};
  // A voice with an absurd spectrum (1e150 m/s²) and then an absurd gain on top: overflow to
  // inf and NaN inside the mix.
  auto loud = testing::catalog_spectrum("stab", "note");
  for (auto& row : loud.amplitude_m_s2)
    for (auto& a : row) a *= 1e150;
  ASSERT_TRUE(engine.load(0, build_voice("loud", testing::small_stylus(), loud, engine.internal_rate(), 5)));
  ASSERT_TRUE(engine.attach(std::make_unique<ConstantStroke>(0.2)));
  ASSERT_TRUE(engine.set_output_level(1e300));
  const auto out = render(engine, 96000, 64);
  for (float x : out) ASSERT_TRUE(std::isfinite(x) && std::abs(x) <= settings.output.limit);
  const auto stats = engine.stats();
  EXPECT_GT(stats.limited_samples + stats.non_finite_samples, 0u);
  EXPECT_LE(stats.peak_output, settings.output.limit);
}

TEST(Engine, NoAllocationOnTheAudioThreadWhileAnotherThreadFloodsIt) {
  Engine engine{EngineSettings{}};
  ASSERT_TRUE(engine.load(0, testing::catalog_voice("stab", "note", engine.internal_rate(), 1)));
  // Voices made beforehand (making them takes a few ms each); the flood swaps them in and out.
  std::vector<std::unique_ptr<Voice>> spare;
  for (std::size_t i = 0; i < 12; ++i)
    spare.push_back(testing::catalog_voice(i % 2 ? "cryon" : "vero2", "note", engine.internal_rate(), 10 + i));
  std::atomic<bool> done{false};
  std::size_t swaps = 0, contacts = 0;
  std::atomic<std::size_t> swaps_seen{0}, contacts_seen{0};
  std::thread control([&] {
    std::size_t i = 0;
    while (!done.load()) {
      contacts += engine.set_contact(0.02 + 0.2 * ((i % 100) / 100.0), 1.0 + (i % 7) * 0.3);
      contacts_seen = contacts;
      if (i % 50 == 0 && !spare.empty()) {
        if (engine.load(i / 50 % 3, std::move(spare.back()))) {
          spare.pop_back();
          swaps_seen = ++swaps;
        }
        engine.select(i / 50 % 3);
      }
      if (i % 500 == 0) engine.attach(std::make_unique<SweepStroke>());
      engine.collect();
      ++i;
      std::this_thread::yield();
    }
  });
  std::vector<float> block(64);
  render(engine, 64, 64);  // first call: nothing special, but leave it out of the count anyway
  const std::size_t before = nibrig::testing::allocations_on_this_thread();
  // At least 8 s of 48 kHz, and on until the flood has really flooded (a loaded CI machine may
  // schedule the control thread late): bounded at 400 s of audio.
  std::uint64_t blocks = 0;
  for (; blocks < 6000 || ((swaps_seen.load() <= 5 || contacts_seen.load() <= 100) && blocks < 300000);
       ++blocks) {
    engine.render(block.data(), block.size());
    if (blocks % 8 == 0) std::this_thread::yield();  // let the flood in between blocks
  }
  const std::size_t allocated = nibrig::testing::allocations_on_this_thread() - before;
  done = true;
  control.join();
  EXPECT_EQ(allocated, 0u);
  EXPECT_GT(swaps, 5u);
  EXPECT_GT(contacts, 100u);
  const auto stats = engine.stats();
  EXPECT_EQ(stats.callbacks, blocks + 1);
  std::uint64_t histogram_total = 0;
  for (auto n : stats.callback_time_histogram) histogram_total += n;
  EXPECT_EQ(histogram_total, stats.callbacks);
  EXPECT_GT(stats.callback_time_quantile(0.5), 0.0);
  EXPECT_LE(stats.callback_time_quantile(0.5), stats.callback_time_quantile(0.99));
}

}  // namespace
}  // namespace nibrig::rt

namespace nibrig::rt {
namespace {

TEST(Engine, ACalibrationFilterShapesTheMixBeforeTheDevice) {
  auto plain = engine_with({"stab"}, 0, std::make_unique<ConstantStroke>(0.1));
  auto calibrated = engine_with({"stab"}, 0, std::make_unique<ConstantStroke>(0.1));
  // A one-tap filter of gain 2 (the simplest inverse filter): every output sample doubles, up
  // to float rounding, since everything after the mix is linear below the limiter.
  const std::vector<double> taps{2.0};
  ASSERT_TRUE(calibrated->set_calibration(std::make_unique<FirFilter>(taps)));
  const auto a = render(*plain, 48000, 64);
  const auto b = render(*calibrated, 48000, 64);
  double peak = 0;
  for (float x : a) peak = std::max(peak, double{std::abs(x)});
  ASSERT_LT(2 * peak, EngineSettings{}.output.limit);
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(b[i], 2 * a[i], 1e-6 * peak) << i;
  // Removed again: back to the plain output's level (the filter is swapped, not faded; the DC
  // blocker's 32 ms memory of the doubled signal dies away within the first quarter second).
  ASSERT_TRUE(calibrated->set_calibration(nullptr));
  const auto c = render(*calibrated, 24000, 64);
  const auto d = render(*plain, 24000, 64);
  EXPECT_NEAR(rms(c, 12000, 24000) / rms(d, 12000, 24000), 1.0, 0.01);
}

}  // namespace
}  // namespace nibrig::rt
