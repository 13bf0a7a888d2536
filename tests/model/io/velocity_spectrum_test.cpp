// The row of a spectrum nearest a speed (the Fig. 14 plot compares at the nearest measured speed).
#include "model/io/velocity_spectrum.hpp"

#include <gtest/gtest.h>

namespace nibrig::model::io {
namespace {

TEST(VelocitySpectrum, NearestSpeedRowPicksTheClosestAndTheFirstOfATie) {
  VelocitySpectrum s;
  s.speeds_m_s = {0.017, 0.05, 0.11, 0.25};
  EXPECT_EQ(nearest_speed_row(s, 0.0), 0u);
  EXPECT_EQ(nearest_speed_row(s, 0.06), 1u);
  EXPECT_EQ(nearest_speed_row(s, 0.2), 3u);
  VelocitySpectrum tie;
  tie.speeds_m_s = {0.25, 0.5, 0.75};
  EXPECT_EQ(nearest_speed_row(tie, 0.625), 1u);  // 0.125 from 0.5 and from 0.75, exactly: the first
  EXPECT_EQ(nearest_speed_row(s, 1.0), 3u);
  EXPECT_EQ(nearest_speed_row(VelocitySpectrum{}, 0.1), 0u);
}

}  // namespace
}  // namespace nibrig::model::io
