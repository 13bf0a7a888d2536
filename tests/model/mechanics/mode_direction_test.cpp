// The share of a mode's motion along each axis, on shapes whose shares are known by construction.
#include "model/mechanics/mode_direction.hpp"

#include <gtest/gtest.h>

namespace nibrig::model::mechanics {
namespace {

TEST(ModeDirection, SharesOfSquaredDisplacementPerAxis) {
  // Two nodes: (1, 0, 2) and (0, 1, 2): x² = 1, y² = 1, z² = 8 of 10.
  Eigen::VectorXd shape(6);
  shape << 1, 0, 2, 0, -1, -2;
  const auto f = displacement_fractions(shape);
  EXPECT_DOUBLE_EQ(f[0], 0.1);
  EXPECT_DOUBLE_EQ(f[1], 0.1);
  EXPECT_DOUBLE_EQ(f[2], 0.8);
  // A pure z bending shape is all z, whatever its sign and scale.
  Eigen::VectorXd z(6);
  z << 0, 0, -3, 0, 0, 0.5;
  EXPECT_EQ(displacement_fractions(z), (std::array<double, 3>{0.0, 0.0, 1.0}));
  EXPECT_EQ(displacement_fractions(Eigen::VectorXd::Zero(6)), (std::array<double, 3>{0.0, 0.0, 0.0}));
}

}  // namespace
}  // namespace nibrig::model::mechanics
