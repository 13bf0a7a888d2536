// A precomputed simulation basis (paper Sec. 5.1, App. A.4-A.5): the response of a tool to a unit
// sine and a unit cosine force at each frequency of a grid, from rest, sampled at a rate. The
// response to any sum of sinusoids on that grid is then a scaled sum of basis rows, without
// stepping.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "model/modal/frequency_response.hpp"
#include "model/modal/modal_model.hpp"

namespace nibrig::model::modal {

class FrequencyResponseBasis {
 public:
  // Simulates every frequency exactly (as simulate_sinusoids does). Memory: 2 · frequencies ·
  // samples doubles (500 frequencies × 1 s at 48 kHz is 384 MB); time grows with modes ·
  // frequencies · samples. Throws std::invalid_argument on a bad model, sample rate or frequency
  // (finite, ≥ 0).
  FrequencyResponseBasis(const ModalModel& model, double sample_rate, std::size_t samples,
                         std::vector<double> frequencies = default_frequency_grid());

  const std::vector<double>& frequencies() const { return frequencies_; }
  double sample_rate() const { return sample_rate_; }
  std::size_t samples() const { return samples_; }

  // Sensor acceleration (m/s²) for the force sin(2πf_k t) N, and for cos(2πf_k t) N, from rest.
  std::span<const double> sine_response(std::size_t k) const;
  std::span<const double> cosine_response(std::size_t k) const;

  // Response to Σ_k amplitudes[k] · sin(2πf_k t + phases[k]) (N, rad), one entry per grid
  // frequency: A sin(Ωt + φ) = A cos φ · sin Ωt + A sin φ · cos Ωt, so it is Σ_k of the two rows so
  // weighted. Throws std::invalid_argument when the sizes differ from frequencies() or a value is
  // not finite.
  std::vector<double> synthesize(std::span<const double> amplitudes,
                                 std::span<const double> phases) const;

 private:
  std::vector<double> frequencies_;
  double sample_rate_;
  std::size_t samples_;
  std::vector<double> sine_;    // frequency-major: row k is sine_[k·samples_ …]
  std::vector<double> cosine_;  // same layout
};

}  // namespace nibrig::model::modal
