// The offline render writes exactly what the engine renders, block by block, into a float WAV.
#include "playback/offline_render.hpp"

#include <gtest/gtest.h>
#include <sndfile.h>

#include <cmath>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <vector>

#include "tests/support/test_paths.hpp"

namespace nibrig::playback {
namespace {

// A renderer whose output is a pure function of the frame index.
class Ramp final : public rt::BlockRenderer {
 public:
  void render(float* out, std::size_t frames) noexcept override {
    for (std::size_t i = 0; i < frames; ++i, ++n_) out[i] = std::sin(0.001f * static_cast<float>(n_ % 100000));
  }

 private:
  std::size_t n_ = 0;
};

TEST(OfflineRender, WritesTheRenderersSamplesToAFloatWav) {
  const auto dir = nibrig::test::scratch_dir("offline_render");
  Ramp renderer;
  const auto result = render_to_wav(renderer, dir / "out.wav", {48000, 64, 0.5});
  EXPECT_EQ(result.frames, 24000u);
  EXPECT_FALSE(std::filesystem::exists(dir / "out.wav.partial"));
  SF_INFO info{};
  SNDFILE* f = sf_open((dir / "out.wav").c_str(), SFM_READ, &info);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(info.samplerate, 48000);
  EXPECT_EQ(info.channels, 1);
  EXPECT_EQ(info.frames, 24000);
  std::vector<float> x(24000);
  EXPECT_EQ(sf_read_float(f, x.data(), 24000), 24000);
  sf_close(f);
  Ramp reference;
  std::vector<float> y(24000);
  reference.render(y.data(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(x[i], y[i]) << i;  // float WAV: bit-exact
}

TEST(OfflineRender, NamesTheFileItCannotWrite) {
  Ramp renderer;
  try {
    render_to_wav(renderer, "/nonexistent-folder/out.wav", {});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/out.wav"), std::string::npos);
  }
}

TEST(OfflineRender, AFailedRenderLeavesNoHalfFile) {
  // A WAV's name taken by a folder is refused (model/io/atomic_file.hpp), and nothing is left
  // beside it: the folder is the only entry afterwards.
  const auto dir = nibrig::test::scratch_dir("offline_render_failed");
  std::filesystem::create_directories(dir / "out.wav");
  std::ofstream(dir / "out.wav" / "keep") << "x";
  Ramp renderer;
  EXPECT_THROW(render_to_wav(renderer, dir / "out.wav", {48000, 64, 0.1}), std::runtime_error);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1)
      << "a failed render must not leave its half file";
}

// Issue 46: render.tool(speed=1e308, force=1e308, period=10**9) was taken from Python; the ranges
// are the library's, named as the argument that set them.
TEST(OfflineRenderBounds, StrokeAndBlockOutsideTheirRangesAreRefused) {
  rt::StrokeRequest fast;
  fast.speed_m_s = 1e308;
  try {
    check_stroke_request(fast);
    FAIL() << "a speed of 1e308 m/s passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("speed: 1e+308 m/s", 0), 0u) << e.what();
  }
  rt::StrokeRequest heavy;
  heavy.force_n = 1e308;
  EXPECT_THROW(check_stroke_request(heavy), std::invalid_argument);
  rt::StrokeRequest resting;  // 0 is at rest and lifted: allowed
  resting.speed_m_s = 0.0, resting.force_n = 0.0;
  EXPECT_NO_THROW(check_stroke_request(resting));
  EXPECT_THROW(check_render_block(1000000000, "period"), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::playback
