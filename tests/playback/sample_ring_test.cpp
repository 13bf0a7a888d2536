// The capture ring: blocks go through in order across the wrap, a full ring stores what fits.
#include "playback/sample_ring.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

namespace nibrig::playback {
namespace {

TEST(SampleRing, BlocksComeOutInOrderAcrossTheWrap) {
  SampleRing ring(10);  // rounded up to 16
  EXPECT_EQ(ring.capacity(), 16u);
  std::vector<float> in(7);
  std::vector<float> out(7);
  float next = 0.0f;
  float expected = 0.0f;
  for (int round = 0; round < 10; ++round) {  // 70 samples through 16 slots: wraps several times
    std::iota(in.begin(), in.end(), next);
    next += 7.0f;
    ASSERT_EQ(ring.push(in.data(), in.size()), 7u);
    ASSERT_EQ(ring.pop(out.data(), out.size()), 7u);
    for (float x : out) EXPECT_EQ(x, expected++);  // exact: samples are copied, not computed
  }
  EXPECT_EQ(ring.size(), 0u);
}

TEST(SampleRing, AFullRingStoresWhatFitsAndKeepsTheOldest) {
  SampleRing ring(8);
  std::vector<float> in(12);
  std::iota(in.begin(), in.end(), 0.0f);
  EXPECT_EQ(ring.push(in.data(), in.size()), 8u);
  EXPECT_EQ(ring.push(in.data(), 1), 0u);
  std::vector<float> out(12, -1.0f);
  EXPECT_EQ(ring.pop(out.data(), out.size()), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(out[i], static_cast<float>(i));
  EXPECT_EQ(ring.pop(out.data(), out.size()), 0u);
}

}  // namespace
}  // namespace nibrig::playback
