// The integrator's own frequency response, checked two independent ways: against the integrator
// itself driven by a sinusoid (steady state), and against the continuous closed form H(f), which it
// must approach as the rate grows.
#include "model/modal/discrete_frequency_response.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "model/modal/frequency_response.hpp"
#include "model/modal/linear_forcing_integrator.hpp"

namespace nibrig::model::modal {
namespace {

ModalModel stylus_like() {
  const double tau = 2 * std::numbers::pi;
  return {{tau * 92.7, tau * 250.0, tau * 1457.5}, {0.36, 0.05, 0.3}, {23.3, 10.0, 33.1}, {0.40, 0.30, 5.1}};
}

TEST(DiscreteFrequencyResponse, EqualsTheIntegratorsSteadyStateResponse) {
  const double fs = 8000;
  LinearForcingIntegrator integrator(stylus_like(), fs);
  for (double f : {30.0, 250.0, 410.0, 3000.0}) {
    const std::vector<double> at{f};
    const auto h = discrete_frequency_response(stylus_like(), fs, at)[0];
    // cos input for 4 s (the slowest mode, ζω ≈ 79/s at 250 Hz, has long decayed by 2 s); fit
    // the last second by projection onto the input's phase.
    integrator.reset();
    const std::size_t n = 4 * 8000;
    std::vector<double> x(n), y(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = std::cos(2 * std::numbers::pi * f * i / fs);
    integrator.process(x.data(), y.data(), n);
    std::complex<double> sum = 0;
    for (std::size_t i = n - 8000; i < n; ++i)
      sum += y[i] * std::polar(1.0, -2 * std::numbers::pi * f * i / fs);
    const std::complex<double> measured = 2.0 * sum / 8000.0;
    // Whole periods in the last second: the projection is exact up to the transient's remains
    // (e^{-79·3} ≈ 1e-103) and rounding.
    EXPECT_NEAR(std::abs(measured - h) / std::abs(h), 0.0, 1e-9) << f;
  }
}

TEST(DiscreteFrequencyResponse, ApproachesTheContinuousResponseAsTheRateGrows) {
  const std::vector<double> f{50, 200, 400};
  const auto continuous = frequency_response(stylus_like(), f);
  double previous = 1e9;
  for (double fs : {4000.0, 16000.0, 64000.0, 256000.0}) {
    const auto d = discrete_frequency_response(stylus_like(), fs, f);
    double worst = 0;
    for (std::size_t k = 0; k < f.size(); ++k)
      worst = std::max(worst, std::abs(std::abs(d[k]) / std::abs(continuous[k]) - 1));
    // The joins' sinc² and the folded images shrink as (f/fs)²: every 4× in rate, ~16× less.
    EXPECT_LT(worst, previous / 8) << fs;
    previous = worst;
  }
  EXPECT_LT(previous, 1e-4);
}

}  // namespace
}  // namespace nibrig::model::modal
