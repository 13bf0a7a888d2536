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

}  // namespace
}  // namespace nibrig::playback
