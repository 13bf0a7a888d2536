// The prepared engine render and the demo write their WAVs with: it must play exactly what an
// engine assembled by hand from the same voices, seeds and stroke plays, so that assembling it here
// changes none of their outputs.
#include "playback/prepared_engine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "model/io/catalog_file.hpp"
#include "rt/voice_builder.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::playback {
namespace {

// Three modes like a printed stylus's first ones (as tests/rt/test_voices.cpp).
model::modal::ModalModel small_stylus() {
  const double tau = 2 * 3.141592653589793;
  return {{tau * 92.7, tau * 250.0, tau * 1457.5}, {0.36, 0.05, 0.3}, {23.3, 10.0, 33.1}, {0.40, 0.30, 5.1}};
}

const model::io::VelocitySpectrum& note_spectrum(const std::string& tool) {
  static const auto catalog = model::io::read_catalog(nibrig::test::assets_dir() / "default_catalog.json");
  for (const auto& p : catalog.pairings)
    if (p.tool == tool && p.surface == "note" && p.vibration) return p.vibration->spectrum;
  throw std::runtime_error("no " + tool + "/note in the bundled catalog");
}

std::vector<float> render(rt::Engine& engine, std::size_t frames) {
  std::vector<float> out(frames);
  for (std::size_t i = 0; i < frames; i += 64) engine.render(out.data() + i, 64);
  return out;
}

TEST(PreparedEngine, PlaysWhatAnEngineAssembledByHandPlays) {
  const auto stylus = small_stylus();
  const std::vector<model::modal::VoiceSource> voices{
      {"stab", "small stylus", stylus, note_spectrum("stab")},
      {"cryon", "small stylus", stylus, note_spectrum("cryon")},
      {"vero2", "small stylus", stylus, note_spectrum("vero2")}};
  PreparedEngine prepared(rt::EngineSettings{}, voices, std::make_unique<rt::SweepStroke>(), 5);
  EXPECT_EQ(prepared.names(), (std::vector<std::string>{"stab", "cryon", "vero2"}));
  EXPECT_EQ(prepared.engine().slots(), 3u);

  // By hand: voice i seeded 5 + i in slot i, slot 0 selected, the sweep attached.
  rt::EngineSettings settings;
  settings.slots = 3;
  rt::Engine engine(settings);
  const char* tools[] = {"stab", "cryon", "vero2"};
  for (std::size_t i = 0; i < 3; ++i)
    engine.load(i, rt::build_voice(tools[i], stylus, note_spectrum(tools[i]), engine.internal_rate(), 5 + i));
  engine.select(0);
  engine.attach(std::make_unique<rt::SweepStroke>());

  // Half a second, then a switch to the triplet's third tool: the same samples, to the bit.
  EXPECT_EQ(render(prepared.engine(), 24000), render(engine, 24000));
  ASSERT_TRUE(prepared.engine().select(2));
  ASSERT_TRUE(engine.select(2));
  const auto switched = render(prepared.engine(), 24000);
  EXPECT_EQ(switched, render(engine, 24000));
  float loudest = 0;
  for (float x : switched) loudest = std::max(loudest, std::abs(x));
  EXPECT_GT(loudest, 1e-4f);  // a tool is heard, so the equality above compares sound
}

TEST(PreparedEngine, RefusesAnEngineWithNothingToPlayOrNoStroke) {
  const model::modal::VoiceSource stab{"stab", "small stylus", small_stylus(), note_spectrum("stab")};
  EXPECT_THROW(PreparedEngine(rt::EngineSettings{}, std::span<const model::modal::VoiceSource>{},
                              std::make_unique<rt::SweepStroke>(), 1),
               std::invalid_argument);
  EXPECT_THROW(PreparedEngine(rt::EngineSettings{}, stab, nullptr, 1), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::playback
