// A lab's forcing model with a hidden truth, for the calibration tests: a model on the catalog's
// own grid (its frequencies and speeds, its six surfaces), and prints of a material or on a surface
// it does not know, simulated through the model from a known curve or forcing with the rig's noise.
// The noise is what one recording carries: the nail pairs' repeatability (two recordings differ by
// it, so each carries it over √2), smoothed over five bins as the catalog's spectra are (so bins
// are correlated, as measured ones are), in log amplitude.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/hermite_curve.hpp"
#include "model/forcing/measurement_repeatability.hpp"
#include "model/io/catalog_file.hpp"
#include "tests/model/forcing/synthetic_exemplars.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::forcing::test {

struct LabTruth {
  ForcingModel model;      // what the lab's calibration starts from: the truth itself
  double noise_log = 0.0;  // one recording's noise, SD of ln M per bin
  double repeatability_db = 0.0;
};

inline LabTruth make_lab_truth(unsigned seed) {
  static const io::Catalog catalog =
      io::read_catalog(nibrig::test::assets_dir() / "default_catalog.json");
  LabTruth truth;
  truth.repeatability_db = nail_pair_repeatability(catalog).rms_db;
  truth.noise_log = truth.repeatability_db / std::sqrt(2.0) * std::log(10.0) / 20.0;
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  ForcingModel& m = truth.model;
  m.knot_frequencies_hz = default_knot_frequencies();
  const auto& grid = catalog.pairings.front().vibration->spectrum;
  m.frequencies_hz = grid.frequencies_hz;
  m.speeds_m_s = grid.speeds_m_s;
  const auto curve = [&](double spread) {
    std::vector<double> knots;
    for (std::size_t k = 0; k < m.knot_frequencies_hz.size(); ++k)
      knots.push_back(spread * normal(rng));
    return knots;
  };
  m.tip_log_gain[0.001] = curve(0.3);
  m.tip_log_gain[0.002] = std::vector<double>(m.knot_frequencies_hz.size(), 0.0);
  m.tip_log_gain[0.004] = curve(0.3);
  m.material_log_gain["vero"] = std::vector<double>(m.knot_frequencies_hz.size(), 0.0);
  m.material_log_gain["DM85"] = curve(0.3);
  for (const auto& s : catalog.surfaces) {
    auto& forcing = m.surface_forcing[s.id];
    for (std::size_t v = 0; v < m.speeds_m_s.size(); ++v) {
      forcing.emplace_back();
      for (std::size_t j = 0; j < m.frequencies_hz.size(); ++j)
        forcing.back().push_back(0.01 * std::exp(normal(rng)));
    }
  }
  return truth;
}

// ln noise per [speed][bin]: N(0,1) smoothed over five bins, scaled to `sd` per bin.
inline std::vector<std::vector<double>> recording_noise(std::size_t speeds, std::size_t bins,
                                                        double sd, std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<std::vector<double>> out;
  for (std::size_t s = 0; s < speeds; ++s) {
    std::vector<double> white(bins + 4);
    for (double& w : white) w = normal(rng);
    out.emplace_back();
    for (std::size_t j = 0; j < bins; ++j) {
      double sum = 0.0;
      for (std::size_t i = 0; i < 5; ++i) sum += white[j + i];
      out.back().push_back(sd * sum / std::sqrt(5.0));  // the mean of 5 has SD 1/√5
    }
  }
  return out;
}

// A print of `material` with tip `tip_m` on `surface`, measured through the model with ln m (or,
// for a surface the model lacks, ln F) replaced by the truth given, and the rig's noise.
inline ForcingExemplar simulated_print(const LabTruth& truth, const std::string& tool,
                                       const std::string& material, double tip_m,
                                       const std::string& surface,
                                       const std::vector<double>& material_knots,
                                       const std::vector<std::vector<double>>& forcing,
                                       std::mt19937& rng) {
  const ForcingModel& m = truth.model;
  ForcingExemplar e;
  e.tool = tool;
  e.surface = surface;
  e.material = material;
  e.tip_diameter_m = tip_m;
  e.response_magnitude = synthetic_response(m.frequencies_hz, 90 + 3e3 * tip_m);
  e.measured.frequencies_hz = m.frequencies_hz;
  e.measured.speeds_m_s = m.speeds_m_s;
  const auto noise =
      recording_noise(m.speeds_m_s.size(), m.frequencies_hz.size(), truth.noise_log, rng);
  for (std::size_t s = 0; s < m.speeds_m_s.size(); ++s) {
    e.measured.amplitude_m_s2.emplace_back();
    for (std::size_t j = 0; j < m.frequencies_hz.size(); ++j) {
      const double f = m.frequencies_hz[j];
      const double log_gain = m.tip_log_gain_at(tip_m, f) +
                              hermite_value(m.knot_frequencies_hz, material_knots, f) + noise[s][j];
      e.measured.amplitude_m_s2.back().push_back(e.response_magnitude[j] * forcing[s][j] *
                                                 std::exp(log_gain));
    }
  }
  return e;
}

}  // namespace nibrig::model::forcing::test
