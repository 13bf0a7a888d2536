// Finding played impulses in a recording: the pulse's correlation properties, lags found to the
// sample through a filter and noise, missing impulses counted and never averaged in.
#include "playback/round_trip.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace nibrig::playback {
namespace {

constexpr std::size_t kRoundTripInterval = 4800;  // 0.1 s at 48 kHz

// A recording of `lags.size()` impulses played kRoundTripInterval apart from frame 1000, each
// arriving `lags[i]` later (negative: not at all), scaled by `gain`, through a one-pole low-pass
// (an actuator's or an input's band limit), plus white noise of rms `noise`.
std::vector<float> recording_with(const std::vector<double>& pulse, const std::vector<long>& lags,
                                  double gain, double noise, std::vector<std::size_t>& played_at) {
  std::vector<double> clean(1000 + kRoundTripInterval * (lags.size() + 1), 0.0);
  played_at.clear();
  for (std::size_t i = 0; i < lags.size(); ++i) {
    played_at.push_back(1000 + i * kRoundTripInterval);
    if (lags[i] < 0) continue;
    for (std::size_t k = 0; k < pulse.size(); ++k)
      clean[played_at.back() + static_cast<std::size_t>(lags[i]) + k] += gain * pulse[k];
  }
  std::mt19937 random(7);
  std::normal_distribution<double> gauss(0.0, noise);
  std::vector<float> out(clean.size());
  double state = 0.0;
  for (std::size_t j = 0; j < clean.size(); ++j) {
    state += 0.5 * (clean[j] - state);
    out[j] = static_cast<float>(state + (noise > 0 ? gauss(random) : 0.0));
  }
  return out;
}

TEST(RoundTripPulse, IsAMaximumLengthSequenceWithASinglePeak) {
  const auto pulse = round_trip_pulse(0.5);
  ASSERT_EQ(pulse.size(), 255u);
  for (double p : pulse) EXPECT_EQ(std::abs(p), 0.5);
  // Periodic autocorrelation of an MLS: N at lag 0 and −1 at every other lag (in units of level²).
  for (std::size_t lag = 0; lag < pulse.size(); ++lag) {
    double sum = 0.0;
    for (std::size_t k = 0; k < pulse.size(); ++k)
      sum += pulse[k] * pulse[(k + lag) % pulse.size()];
    EXPECT_NEAR(sum / 0.25, lag == 0 ? 255.0 : -1.0, 1e-9) << "lag " << lag;
  }
  EXPECT_THROW(round_trip_pulse(0.0), std::invalid_argument);
  EXPECT_THROW(round_trip_pulse(1.5), std::invalid_argument);
}

TEST(FindImpulses, FindsEachLagToTheSampleThroughAFilterAndNoise) {
  const auto pulse = round_trip_pulse(0.25);
  const std::vector<long> lags = {128, 130, 127, 512, 128};
  std::vector<std::size_t> played_at;
  // Noise 30 dB under the pulse, and an inverted chain (gain < 0): both must still be found.
  const auto recorded = recording_with(pulse, lags, -0.3, 0.0024, played_at);
  ImpulseSearch search;
  search.max_lag_samples = kRoundTripInterval - pulse.size();
  const auto found = find_impulses(pulse, played_at, recorded, search);
  ASSERT_EQ(found.size(), lags.size());
  for (std::size_t i = 0; i < lags.size(); ++i) {
    ASSERT_TRUE(found[i]) << "impulse " << i;
    // The one-pole low-pass at this pole delays the pulse's correlation peak by under one sample:
    // the best match stays on the sample the copy starts at.
    EXPECT_EQ(static_cast<long>(found[i]->lag_samples), lags[i]) << "impulse " << i;
    EXPECT_GT(found[i]->correlation, search.threshold);
  }
  const RoundTripStats s = summarise_round_trips(found);
  EXPECT_EQ(s.found, 5u);
  EXPECT_NEAR(s.mean_samples, (128 + 130 + 127 + 512 + 128) / 5.0, 1e-12);
  EXPECT_EQ(s.min_samples, 127u);
  EXPECT_EQ(s.worst_samples, 512u);
  // Sample standard deviation of {128, 130, 127, 512, 128}.
  EXPECT_NEAR(s.stddev_samples, 171.62168, 1e-5);
}

TEST(FindImpulses, AMissingOrBuriedImpulseIsCountedNotAveraged) {
  const auto pulse = round_trip_pulse(0.25);
  std::vector<std::size_t> played_at;
  // The second never arrives; noise alone correlates with the pulse at about 1/√255 ≈ 0.06, far
  // under the threshold of 0.5.
  const auto recorded = recording_with(pulse, {200, -1, 200}, 1.0, 0.001, played_at);
  ImpulseSearch search;
  search.max_lag_samples = kRoundTripInterval - pulse.size();
  auto found = find_impulses(pulse, played_at, recorded, search);
  ASSERT_EQ(found.size(), 3u);
  EXPECT_TRUE(found[0]);
  EXPECT_FALSE(found[1]);
  EXPECT_TRUE(found[2]);
  const RoundTripStats s = summarise_round_trips(found);
  EXPECT_EQ(s.played, 3u);
  EXPECT_EQ(s.found, 2u);
  EXPECT_EQ(s.mean_samples, 200.0);
  EXPECT_EQ(s.worst_samples, 200u);

  // A recording that ends inside an impulse's window cannot say where it was: missing too.
  const std::vector<float> short_recording(recorded.begin(), recorded.begin() + played_at[2] + 100);
  found = find_impulses(pulse, played_at, short_recording, search);
  EXPECT_TRUE(found[0]);
  EXPECT_FALSE(found[2]);
}

TEST(FindImpulses, RefusesAThresholdOutsideTheUnitInterval) {
  const auto pulse = round_trip_pulse(0.25);
  const std::vector<std::size_t> at = {0};
  const std::vector<float> recorded(1000, 0.0f);
  ImpulseSearch search;
  search.threshold = 0.0;
  EXPECT_THROW(find_impulses(pulse, at, recorded, search), std::invalid_argument);
  search.threshold = 1.5;
  EXPECT_THROW(find_impulses(pulse, at, recorded, search), std::invalid_argument);
}

TEST(SummariseRoundTrips, NothingFoundLeavesEveryFigureAtZero) {
  const std::vector<std::optional<FoundImpulse>> none(4);
  const RoundTripStats s = summarise_round_trips(none);
  EXPECT_EQ(s.played, 4u);
  EXPECT_EQ(s.found, 0u);
  EXPECT_EQ(s.mean_samples, 0.0);
}

}  // namespace
}  // namespace nibrig::playback
