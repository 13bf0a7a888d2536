// The interpolator from the voices' 4 kHz to 48 kHz: flat where tools vibrate, images gone, and
// equal results whatever the block sizes.
#include "rt/upsampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace nibrig::rt {
namespace {

// Amplitude of frequency f in x (rate fs), by projection over a whole number of periods.
double amplitude_at(const std::vector<float>& x, std::size_t from, double f, double fs) {
  std::complex<double> sum = 0;
  const std::size_t n = x.size() - from;
  for (std::size_t i = 0; i < n; ++i)
    sum += static_cast<double>(x[from + i]) *
           std::exp(std::complex<double>(0, -2 * std::numbers::pi * f * static_cast<double>(i) / fs));
  return 2 * std::abs(sum) / static_cast<double>(n);
}

std::vector<float> upsample_sine(double f, std::size_t inputs) {
  Upsampler up(12);
  std::vector<double> in(inputs);
  for (std::size_t i = 0; i < inputs; ++i) in[i] = std::sin(2 * std::numbers::pi * f * i / 4000.0);
  std::vector<float> out(inputs * 12);
  up.process(in.data(), out.data(), out.size());
  return out;
}

TEST(Upsampler, FlatTo500HzAndImagesBelowMinus70Db) {
  for (double f : {20.0, 100.0, 250.0, 500.0}) {
    // 1 s of input: every test frequency and image completes whole periods in the last 0.5 s.
    const auto out = upsample_sine(f, 4000);
    const double gain = amplitude_at(out, 24000, f, 48000);
    // Kaiser-windowed sinc, 96 taps: pass-band ripple is ~1e-4; 0.01 dB is the stated promise.
    EXPECT_NEAR(20 * std::log10(gain), 0.0, 0.01) << f;
    for (double image : {4000 - f, 4000 + f, 8000 - f, 8000 + f})
      EXPECT_LT(20 * std::log10(amplitude_at(out, 24000, image, 48000) + 1e-300), -70) << f << " " << image;
  }
}

TEST(Upsampler, BlockSizesDoNotChangeTheOutput) {
  std::vector<double> in(1000);
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = std::sin(0.01 * i * i);
  Upsampler whole(12), pieces(12);
  std::vector<float> a(12000), b(12000);
  whole.process(in.data(), a.data(), a.size());
  std::size_t used = 0, done = 0;
  for (std::size_t block = 1; done < b.size(); block = block % 101 + 7) {
    const std::size_t m = std::min(block, b.size() - done);
    const std::size_t need = pieces.inputs_needed(m);
    pieces.process(in.data() + used, b.data() + done, m);
    used += need;
    done += m;
  }
  EXPECT_EQ(used, in.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << i;
}

// The phases are made side by side in lanes; each output must still be its own sum over the lags
// in order, the same bits as the filter written out one output at a time.
TEST(Upsampler, EveryOutputIsItsPhasesSumInOrder) {
  for (std::size_t factor : {1u, 5u, 6u, 12u, 24u}) {  // one to four vectors of phases, and more
    Upsampler up(factor, 8);
    std::vector<double> in(300);
    for (std::size_t i = 0; i < in.size(); ++i) in[i] = std::sin(0.37 * i) + 1e-3 * i;
    std::vector<float> out(in.size() * factor);
    up.process(in.data(), out.data(), out.size());
    for (std::size_t j = 0; j < out.size(); ++j) {
      const std::size_t newest = j / factor, phase = j % factor;
      double y = 0;
      for (std::size_t l = 0; l < 8; ++l)
        y += up.tap(phase, l) * (newest >= l ? in[newest - l] : 0.0);
      ASSERT_EQ(out[j], static_cast<float>(y)) << factor << " " << j;
    }
  }
}

TEST(Upsampler, ConstantInputGivesConstantOutput) {
  Upsampler up(12);
  std::vector<double> in(100, 0.5);
  std::vector<float> out(1200);
  up.process(in.data(), out.data(), out.size());
  // Each phase sums to 1 (in double; float output rounding only).
  for (std::size_t i = 200; i < out.size(); ++i) ASSERT_NEAR(out[i], 0.5f, 1e-7f);
}

}  // namespace
}  // namespace nibrig::rt
