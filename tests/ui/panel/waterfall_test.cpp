// The waterfall's colours, without a window: rows become colours by the map at the right age, the
// sequential map is viridis from its low to its high end (clamped outside), and a difference of zero
// is the near-white middle of the diverging map.
#include "ui/panel/waterfall.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace nibrig::ui::panel {
namespace {

TEST(Waterfall, EachRowComesBackAtItsAgeInTheMapsColours) {
  Waterfall fall(4, 3, Waterfall::Scale::sequential, -60.0f, 20.0f);
  const std::vector<float> first{-60, -20, 20, 100}, second{20, 20, -60, -1000};
  fall.push_row(first.data());
  fall.push_row(second.data());
  EXPECT_EQ(fall.rows_pushed(), 2u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(fall.colour_at(0, k), sequential_colour(second[k], -60, 20));
    EXPECT_EQ(fall.colour_at(1, k), sequential_colour(first[k], -60, 20));
  }
  // Two more rows wrap the ring of three: the first row is gone, the second is now two old.
  fall.push_row(first.data());
  fall.push_row(first.data());
  EXPECT_EQ(fall.colour_at(2, 0), sequential_colour(second[0], -60, 20));
}

TEST(Waterfall, TheSequentialMapIsViridisClampedAtItsEnds) {
  // matplotlib's viridis at 0 and 1: (68, 1, 84) and (253, 231, 37).
  EXPECT_EQ(sequential_colour(-60, -60, 20), (Rgba{68, 1, 84, 255}));
  EXPECT_EQ(sequential_colour(20, -60, 20), (Rgba{253, 231, 37, 255}));
  EXPECT_EQ(sequential_colour(-500, -60, 20), sequential_colour(-60, -60, 20));
  EXPECT_EQ(sequential_colour(500, -60, 20), sequential_colour(20, -60, 20));
  // Brighter as the level rises (the map's green channel grows monotonically).
  int last = -1;
  for (float db = -60; db <= 20; db += 5) {
    const int g = sequential_colour(db, -60, 20).g;
    EXPECT_GT(g, last);
    last = g;
  }
}

TEST(Waterfall, ADifferenceOfZeroIsNearWhiteAndItsSignIsRedOrBlue) {
  const Rgba zero = diverging_colour(0, 20), more = diverging_colour(20, 20), less = diverging_colour(-20, 20);
  EXPECT_GT(zero.r, 230);
  EXPECT_GT(zero.g, 230);
  EXPECT_GT(zero.b, 230);
  EXPECT_GT(more.r, 2 * more.b);  // the simulation louder: red
  EXPECT_GT(less.b, 2 * less.r);  // quieter: blue
  EXPECT_EQ(diverging_colour(1e9f, 20), more);
}

}  // namespace
}  // namespace nibrig::ui::panel
