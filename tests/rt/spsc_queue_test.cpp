#include "rt/spsc_queue.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <thread>

#include "tests/support/allocation_counter.hpp"

namespace nibrig::rt {
namespace {

TEST(SpscQueue, HoldsItsCapacityInOrderAcrossTheWrap) {
  SpscQueue<int> q(3);
  EXPECT_EQ(q.capacity(), 4u);  // rounded up to a power of two
  for (int round = 0; round < 5; ++round) {  // indices wrap several times
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(q.try_push(10 * round + i));
    EXPECT_FALSE(q.try_push(99));  // full: refused, not overwritten
    for (int i = 0; i < 4; ++i) EXPECT_EQ(q.try_pop(), 10 * round + i);
    EXPECT_FALSE(q.try_pop().has_value());
  }
  EXPECT_THROW(SpscQueue<int>(0), std::invalid_argument);
}

TEST(SpscQueue, PopLatestKeepsOnlyTheNewest) {
  SpscQueue<double> q(8);
  EXPECT_FALSE(q.pop_latest().has_value());
  for (double v : {0.1, 0.2, 0.3}) q.try_push(v);
  EXPECT_EQ(q.pop_latest(), 0.3);
  EXPECT_FALSE(q.try_pop().has_value());
}

TEST(SpscQueue, TwoThreadsPassAMillionItemsInOrderWithoutAllocating) {
  // The consumer plays the audio thread: it must see every item exactly once, in order, and
  // allocate nothing while doing so.
  constexpr std::uint64_t kItems = 1'000'000;
  SpscQueue<std::uint64_t> q(64);
  std::thread producer([&] {
    for (std::uint64_t i = 0; i < kItems;)
      if (q.try_push(i)) ++i;
  });
  const std::size_t before = nibrig::testing::allocations_on_this_thread();
  std::uint64_t expected = 0;
  bool in_order = true;
  while (expected < kItems) {
    if (const auto item = q.try_pop()) {
      in_order = in_order && *item == expected;
      ++expected;
    }
  }
  const std::size_t allocated = nibrig::testing::allocations_on_this_thread() - before;
  producer.join();
  EXPECT_TRUE(in_order);
  EXPECT_EQ(allocated, 0u);
}

}  // namespace
}  // namespace nibrig::rt

namespace nibrig::rt {
namespace {

TEST(AllocationCounter, SeesTheAllocationsItMustRuleOut) {
  // Without this the zero counts above could come from a counter that never counts.
  // Through a volatile pointer: an optimiser may elide a new-expression whose result is unused.
  static void* volatile sink = nullptr;
  const std::size_t before = nibrig::testing::allocations_on_this_thread();
  sink = new std::uint64_t(7);
  const std::size_t after = nibrig::testing::allocations_on_this_thread();
  delete static_cast<std::uint64_t*>(sink);
  EXPECT_EQ(after - before, 1u);
}

}  // namespace
}  // namespace nibrig::rt
