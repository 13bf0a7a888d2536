// The stream's bookkeeping on hand-made sequences: every number is delivered once, dropped, late or
// a duplicate, and the counts say which.
#include "rig/usb/sequence_tracker.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace nibrig::rig::usb {
namespace {

using V = SequenceTracker::Verdict;

TEST(SequenceTracker, AGapIsCountedAsDropped) {
  SequenceTracker t;
  for (std::uint32_t s : {10u, 11u, 12u, 15u, 16u}) EXPECT_EQ(t.observe(s), V::kDeliver) << s;
  EXPECT_EQ(t.dropped(), 2u);  // 13 and 14
  EXPECT_EQ(t.late(), 0u);
}

TEST(SequenceTracker, ALateFrameIsReorderedNotDroppedAndNotDeliveredTwice) {
  SequenceTracker t;
  std::vector<V> verdicts;
  for (std::uint32_t s : {1u, 2u, 4u, 3u, 5u, 3u}) verdicts.push_back(t.observe(s));
  EXPECT_EQ(verdicts, (std::vector<V>{V::kDeliver, V::kDeliver, V::kDeliver, V::kLate, V::kDeliver,
                                      V::kDuplicate}));
  EXPECT_EQ(t.dropped(), 0u);  // 3 came after all
  EXPECT_EQ(t.late(), 1u);
  EXPECT_EQ(t.duplicates(), 1u);
}

TEST(SequenceTracker, WrapsAtTwoToTheThirtyTwoAsTheWireDoes) {
  SequenceTracker t;
  for (std::uint32_t s : {0xFFFFFFFEu, 0xFFFFFFFFu, 0u, 2u}) EXPECT_EQ(t.observe(s), V::kDeliver);
  EXPECT_EQ(t.dropped(), 1u);  // only 1 is missing
}

TEST(SequenceTracker, ARestartTakesTheNextFrameAsItsBaseline) {
  SequenceTracker t;
  t.observe(5);
  t.restart();
  EXPECT_EQ(t.observe(1000), V::kDeliver);
  EXPECT_EQ(t.dropped(), 0u);
}

}  // namespace
}  // namespace nibrig::rig::usb
