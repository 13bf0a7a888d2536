#include "playback/round_trip.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace nibrig::playback {

std::vector<double> round_trip_pulse(double level) {
  if (!(level > 0.0 && level <= 1.0))
    throw std::invalid_argument("the impulse's level must be in (0, 1] of full scale, not " +
                                std::to_string(level));
  // An 8-bit Fibonacci LFSR with taps 8, 6, 5, 4 (x^8 + x^6 + x^5 + x^4 + 1, a primitive
  // polynomial) runs through all 255 non-zero states before it repeats.
  std::vector<double> pulse;
  pulse.reserve(255);
  std::uint32_t state = 1;
  for (int i = 0; i < 255; ++i) {
    pulse.push_back((state & 1u) ? level : -level);
    const std::uint32_t bit = (state ^ (state >> 2) ^ (state >> 3) ^ (state >> 4)) & 1u;
    state = (state >> 1) | (bit << 7);
  }
  return pulse;
}

std::vector<std::optional<FoundImpulse>> find_impulses(std::span<const double> pulse,
                                                       std::span<const std::size_t> played_at,
                                                       std::span<const float> recorded,
                                                       const ImpulseSearch& search) {
  if (pulse.empty()) throw std::invalid_argument("find_impulses: the pulse is empty");
  if (!(search.threshold > 0.0 && search.threshold <= 1.0))
    throw std::invalid_argument("find_impulses: the threshold must be in (0, 1], not " +
                                std::to_string(search.threshold));
  const std::size_t n = pulse.size();
  double pulse_energy = 0.0;
  for (double p : pulse) pulse_energy += p * p;
  if (!(pulse_energy > 0.0)) throw std::invalid_argument("find_impulses: the pulse is silent");

  std::vector<std::optional<FoundImpulse>> out;
  out.reserve(played_at.size());
  for (std::size_t at : played_at) {
    const std::size_t end = at + search.max_lag_samples + n;  // one past the last sample read
    if (end > recorded.size()) {
      out.emplace_back(std::nullopt);
      continue;
    }
    // The window's energy slides along with the lag: add the sample entering, drop the one leaving.
    double window_energy = 0.0;
    FoundImpulse best;
    for (std::size_t lag = 0; lag <= search.max_lag_samples; ++lag) {
      const float* window = recorded.data() + at + lag;
      if (lag % n == 0) {
        // Summed afresh once a pulse length, so that the sliding sum's rounding (about 1e-16 of
        // the pulse that passed) never makes digital silence look like a faint signal.
        window_energy = 0.0;
        for (std::size_t k = 0; k < n; ++k) window_energy += double{window[k]} * window[k];
      } else {
        const double leaving = window[-1], entering = window[n - 1];
        window_energy = std::max(0.0, window_energy - leaving * leaving + entering * entering);
      }
      if (window_energy <= 0.0) continue;  // digital silence correlates with nothing
      double dot = 0.0;
      for (std::size_t k = 0; k < n; ++k) dot += pulse[k] * window[k];
      const double rho = std::abs(dot) / std::sqrt(pulse_energy * window_energy);
      if (rho > best.correlation) best = FoundImpulse{lag, rho};
    }
    if (best.correlation >= search.threshold) {
      out.emplace_back(best);
    } else {
      out.emplace_back(std::nullopt);
    }
  }
  return out;
}

RoundTripStats summarise_round_trips(std::span<const std::optional<FoundImpulse>> found) {
  RoundTripStats s;
  s.played = found.size();
  double sum = 0.0;
  for (const auto& f : found) {
    if (!f) continue;
    if (s.found == 0) {
      s.min_samples = s.worst_samples = f->lag_samples;
      s.weakest_correlation = f->correlation;
    }
    ++s.found;
    sum += static_cast<double>(f->lag_samples);
    s.min_samples = std::min(s.min_samples, f->lag_samples);
    s.worst_samples = std::max(s.worst_samples, f->lag_samples);
    s.weakest_correlation = std::min(s.weakest_correlation, f->correlation);
  }
  if (s.found == 0) return s;
  s.mean_samples = sum / static_cast<double>(s.found);
  if (s.found > 1) {
    double squares = 0.0;
    for (const auto& f : found)
      if (f) squares += std::pow(static_cast<double>(f->lag_samples) - s.mean_samples, 2);
    s.stddev_samples = std::sqrt(squares / static_cast<double>(s.found - 1));
  }
  return s;
}

}  // namespace nibrig::playback
