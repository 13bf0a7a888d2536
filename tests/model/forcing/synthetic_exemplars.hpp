// Exemplars generated from a known forcing model (F per surface cell, t and m curves with the
// references pinned at zero, a response H per design), so that a fit can be checked against the
// truth it came from.
#pragma once

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/hermite_curve.hpp"

namespace nibrig::model::forcing::test {

struct SyntheticTool {
  std::string material;
  double tip_diameter_m;
};

struct SyntheticTruth {
  std::vector<double> knots = default_knot_frequencies();
  std::map<double, std::vector<double>> tip;                        // ln t knot values
  std::map<std::string, std::vector<double>> material;              // ln m knot values
  std::map<std::string, std::vector<std::vector<double>>> forcing;  // F_S[speed][bin], N
  std::vector<ForcingExemplar> exemplars;
};

// A small grid keeps the brute-force reference (F as explicit unknowns) cheap: 25 bins from 10 to
// 490 Hz (two or three per knot interval, enough to pin all eleven knots) and two speeds.
inline std::vector<double> synthetic_frequencies() {
  std::vector<double> f;
  for (double x = 10; x <= 490; x += 20) f.push_back(x);
  return f;
}

// |H| of a one-mode stylus whose resonance moves with the design, so designs differ.
inline std::vector<double> synthetic_response(const std::vector<double>& frequencies,
                                              double resonance_hz) {
  std::vector<double> h;
  for (double f : frequencies) {
    const double r = f / resonance_hz;
    h.push_back(r * r / std::hypot(1 - r * r, 0.1 * r) + 0.05);
  }
  return h;
}

// Surfaces "a" (every tool), "b" and "c" (some tools each); materials vero (reference), DM95, DM85;
// tips 1, 2 (reference), 4 mm. ln of every truth value is drawn from N(0, spread²)-ish ranges.
inline SyntheticTruth make_synthetic_truth(unsigned seed = 7) {
  SyntheticTruth truth;
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const std::vector<double> frequencies = synthetic_frequencies();
  const std::vector<double> speeds{0.05, 0.2};
  auto curve = [&](bool reference) {
    std::vector<double> knots(truth.knots.size(), 0.0);
    if (!reference)
      for (double& k : knots) k = 0.5 * normal(rng);
    return knots;
  };
  for (double d : {0.001, 0.002, 0.004}) truth.tip[d] = curve(d == 0.002);
  for (const std::string m : {"vero", "DM95", "DM85"}) truth.material[m] = curve(m == "vero");

  const std::map<std::string, std::vector<SyntheticTool>> surfaces{
      {"a",
       {{"vero", 0.001},
        {"vero", 0.002},
        {"vero", 0.004},
        {"DM95", 0.001},
        {"DM95", 0.002},
        {"DM95", 0.004},
        {"DM85", 0.001},
        {"DM85", 0.002},
        {"DM85", 0.004}}},
      {"b", {{"vero", 0.002}, {"DM95", 0.001}, {"DM85", 0.004}, {"vero", 0.004}, {"DM85", 0.001}}},
      {"c", {{"vero", 0.001}, {"DM95", 0.004}, {"DM85", 0.002}, {"DM95", 0.002}}}};
  for (const auto& [surface, tools] : surfaces) {
    auto& forcing = truth.forcing[surface];
    for (std::size_t s = 0; s < speeds.size(); ++s) {
      forcing.emplace_back();
      for (std::size_t j = 0; j < frequencies.size(); ++j)
        forcing.back().push_back(0.01 * std::exp(normal(rng)));
    }
    for (const auto& tool : tools) {
      ForcingExemplar e;
      e.tool = tool.material + std::to_string(static_cast<int>(tool.tip_diameter_m * 1e3));
      e.surface = surface;
      e.material = tool.material;
      e.tip_diameter_m = tool.tip_diameter_m;
      const double resonance = 90 + 3e3 * tool.tip_diameter_m + (tool.material == "DM85" ? 7 : 0);
      e.response_magnitude = synthetic_response(frequencies, resonance);
      e.measured.frequencies_hz = frequencies;
      e.measured.speeds_m_s = speeds;
      for (std::size_t s = 0; s < speeds.size(); ++s) {
        std::vector<double> row;
        for (std::size_t j = 0; j < frequencies.size(); ++j) {
          const double f = frequencies[j];
          const double log_gain = hermite_value(truth.knots, truth.tip.at(tool.tip_diameter_m), f) +
                                  hermite_value(truth.knots, truth.material.at(tool.material), f);
          row.push_back(e.response_magnitude[j] * forcing[s][j] * std::exp(log_gain));
        }
        e.measured.amplitude_m_s2.push_back(row);
      }
      truth.exemplars.push_back(e);
    }
  }
  return truth;
}

// Multiplies every amplitude by exp(σ·N(0,1)): measurement noise in log amplitude.
inline void add_log_noise(std::vector<ForcingExemplar>& exemplars, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  for (auto& e : exemplars)
    for (auto& row : e.measured.amplitude_m_s2)
      for (double& a : row) a *= std::exp(normal(rng));
}

}  // namespace nibrig::model::forcing::test
