#include "rig/clock_fit.hpp"

#include <gtest/gtest.h>

#include <random>

namespace nibrig::rig {
namespace {

// A device clock running 50 ppm fast, stamps every ms, each arriving after 1 ms of fixed latency
// plus an exponential wait (mean 2 ms, as USB polling and scheduling give), for 30 s. The lower
// envelope recovers the true mapping (device → host without the random part) to well under the
// random part's mean: within 0.1 ms over the whole run, and the drift to within 2 ppm.
TEST(ClockFit, RecoversOffsetAndDriftFromJitteredArrivals) {
  std::mt19937_64 random(42);
  std::exponential_distribution<double> wait(1.0 / 0.002);
  const double ppm = 50.0, start_host = 1234.5, latency = 0.001;
  const auto true_host = [&](double device) { return start_host + device / (1.0 + ppm * 1e-6); };
  ClockFit fit;
  for (int k = 0; k < 30000; ++k) {
    const double device = k * 1e-3;
    fit.add(device, true_host(device) + latency + wait(random));
  }
  ASSERT_TRUE(fit.ready());
  EXPECT_NEAR(fit.drift_ppm(), ppm, 2.0);
  double worst = 0.0;
  for (double device = 1.0; device < 29.0; device += 0.5)
    worst = std::max(worst, std::abs(fit.host_time(device) - (true_host(device) + latency)));
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(fit.residual_s(), 1e-4);
  for (double device = 1.0; device < 29.0; device += 7.0)
    EXPECT_NEAR(fit.device_time(fit.host_time(device)), device, 1e-9);  // the inverse
}

// A clock without drift and without jitter: exact.
TEST(ClockFit, ExactForAPerfectClock) {
  ClockFit fit(0.1);
  for (int k = 0; k < 2000; ++k) fit.add(k * 1e-3, 10.0 + k * 1e-3);
  EXPECT_NEAR(fit.host_time(1.5), 11.5, 1e-12);
  EXPECT_NEAR(fit.drift_ppm(), 0.0, 1e-6);
  EXPECT_NEAR(fit.residual_s(), 0.0, 1e-12);
}

TEST(ClockFit, NeedsTwoWindowsAndIgnoresStampsGoingBack) {
  ClockFit fit(1.0);
  EXPECT_FALSE(fit.ready());
  fit.add(0.0, 5.0);
  EXPECT_DOUBLE_EQ(fit.host_time(0.5), 5.5);  // the only offset seen so far
  fit.add(1.0, 6.0);
  fit.add(0.5, 100.0);  // older than the last stamp: ignored
  fit.add(2.0, 7.0);
  EXPECT_TRUE(fit.ready());
  EXPECT_NEAR(fit.host_time(3.0), 8.0, 1e-12);
  EXPECT_THROW(ClockFit(0.0), std::invalid_argument);
  EXPECT_THROW(ClockFit(1.0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::rig
