// Which modes a tip force drives: a hand-made model with two modes the tip cannot reach.
#include "model/modal/tip_driven_modes.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace nibrig::model::modal {
namespace {

// ω / 2π of 2π·f is f to a few ulps.
void expect_hz(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << i;
}

TEST(TipDrivenModes, SkipsModesTheTipDoesNotReach) {
  const double tau = 2 * std::numbers::pi;
  ModalModel m;
  m.omega = {tau * 10, tau * 20, tau * 30, tau * 40, tau * 50};
  m.zeta = {0.01, 0.01, 0.01, 0.01, 0.01};
  // Participation 2, ~0 (1e-6 of the largest: an in-plane mode), -1, 0 (torsion), 0.5.
  m.input = {2.0, 2e-6, -1.0, 0.0, 0.5};
  m.output = {1, 1, 1, 1, 1};
  expect_hz(tip_driven_frequencies_hz(m, 3), {10.0, 30.0, 50.0});
  expect_hz(tip_driven_frequencies_hz(m, 2), {10.0, 30.0});
  // With a looser threshold the in-plane mode counts.
  expect_hz(tip_driven_frequencies_hz(m, 2, 1e-7), {10.0, 20.0});
}

}  // namespace
}  // namespace nibrig::model::modal
