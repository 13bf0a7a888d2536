// A voice end to end: forcing generator → exact modal integrator at 8 kHz. Its output must read,
// through the catalog's analysis, as the measured acceleration it was made from (the forcing was
// the measurement divided by the stylus's response; the integrator multiplies it back exactly).
#include "rt/voice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "model/modal/discrete_frequency_response.hpp"
#include "tests/rt/spectrum_check.hpp"
#include "tests/rt/test_voices.hpp"
#include "tests/support/allocation_counter.hpp"

namespace nibrig::rt {
namespace {

using testing::kInternalRate;

TEST(Voice, OutputReadsAsTheMeasuredAccelerationSpectrum) {
  const auto measured = testing::catalog_spectrum("stab", "note");
  const auto response = model::modal::discrete_frequency_response(testing::small_stylus(), kInternalRate,
                                                                  measured.frequencies_hz);
  double peak = 0;
  for (const auto& h : response) peak = std::max(peak, std::abs(h));
  for (std::size_t s : {0u, 3u, 5u}) {
    auto voice = testing::catalog_voice("stab", "note", kInternalRate, 21 + s);
    const std::size_t n = 150 * 12000;  // 150 analysis windows of 1.5 s
    std::vector<double> v(n, measured.speeds_m_s[s]), f(n, kReferenceNormalForce), a(n);
    voice->process(v.data(), f.data(), a.data(), n);
    // Compare where the regularised division was a plain one (|H| ≥ 3 % of its peak: the
    // regulariser changes the forcing by at most 0.1 %), and away from the band edges (6-10,
    // 494-498 Hz, where the generator's window spreads the target's edge).
    std::vector<double> frequencies, want;
    for (std::size_t k = 3; k + 3 < measured.frequencies_hz.size(); ++k)
      if (std::abs(response[k]) >= 0.03 * peak) {
        frequencies.push_back(measured.frequencies_hz[k]);
        want.push_back(measured.amplitude_m_s2[s][k]);
      }
    ASSERT_GT(frequencies.size(), want.size() / 2);
    const auto a_read = testing::catalog_analysis(a, kInternalRate, frequencies);
    const auto agreement = testing::compare_spectra(a_read, want);
    // As for the forcing alone (forcing_generator_test.cpp: the catalog spectrum's own roughness
    // dominates); the integrator adds no error, since the forcing was divided by its own discrete
    // response. Same tolerances.
    EXPECT_LT(std::abs(agreement.total_db), 0.25) << s;
    EXPECT_LT(agreement.median_abs_db, 0.5) << s;
    EXPECT_LT(agreement.p95_abs_db, 1.5) << s;
    std::printf("stab/note at %.1f mm/s: total %+.3f dB, median %.3f dB, p95 %.3f dB over %zu points\n",
                measured.speeds_m_s[s] * 1000, agreement.total_db, agreement.median_abs_db,
                agreement.p95_abs_db, frequencies.size());
  }
}

TEST(Voice, ProcessingAllocatesNothing) {
  auto voice = testing::catalog_voice("cryon", "stone", kInternalRate, 1);
  std::vector<double> v(10000, 0.12), f(10000, 2.2), a(10000);
  const std::size_t before = nibrig::testing::allocations_on_this_thread();
  for (std::size_t at = 0; at < v.size(); at += 53)
    voice->process(v.data() + at, f.data() + at, a.data() + at, std::min<std::size_t>(53, v.size() - at));
  EXPECT_EQ(nibrig::testing::allocations_on_this_thread(), before);
}

}  // namespace
}  // namespace nibrig::rt
