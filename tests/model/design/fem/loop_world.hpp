// A simulated world for the design loop whose truth the model does not know: the prints of the
// vero–DM85 range are made by materials whose moduli, forcing curves and mixing differ from the
// model's, and measured with the measurement's own noise. Shared by the world's tests.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "model/design/design_loop.hpp"
#include "model/design/design_response_grid.hpp"
#include "model/design/loop_model.hpp"
#include "model/design/prediction_inputs.hpp"
#include "model/forcing/forcing_inputs.hpp"
#include "model/forcing/hermite_curve.hpp"
#include "model/measure/descriptors.hpp"
#include "model/mechanics/material_table.hpp"

namespace nibrig::model::design::test {

// How far the truth lies from the model, by the spread between the paper's printed tools. The
// forcing curves and the mixing rule: a smooth random curve per material (and one for a mix's bow,
// 4f·(1 − f) times it) whose knots have the RMS of the paper's material curves. μ: an offset per
// material with the sd of μ between the paper's printed tools on the surface (a lab's finish and
// cleaning move it). The moduli: log-normal with sd 0.2, as the table's DM85 is an estimate from
// Shore hardness, whose conversions differ by tens of per cent.
struct WorldSpread {
  double curve_sd = 0.0;  // natural log, per knot
  double curve_correlation_hz = 150.0;
  double mu_sd = 0.0;
  double modulus_log_sd = 0.2;
};

struct LoopWorld {
  forcing::ForcingModel truth_model;
  std::vector<double> mixing_bow;  // knots of ln m's bow at f = ½, times 4f(1 − f)
  mechanics::MaterialTable truth_materials;
  DesignResponseGrid truth_grid;
  PredictionSetup truth_setup;  // points into this world: the world stays put
  double mu_offset_first = 0.0, mu_offset_second = 0.0;
  double vero_modulus_ratio = 1.0, dm85_modulus_ratio = 1.0;
};

inline std::vector<double> smooth_random_curve(const std::vector<double>& knots, double sd,
                                               double correlation_hz, std::mt19937_64& rng) {
  const auto n = static_cast<Eigen::Index>(knots.size());
  Eigen::MatrixXd k(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      const double d = (knots[static_cast<std::size_t>(i)] - knots[static_cast<std::size_t>(j)]) /
                       correlation_hz;
      k(i, j) = sd * sd * std::exp(-0.5 * d * d) + (i == j ? 1e-10 : 0.0);
    }
  const Eigen::MatrixXd l = k.llt().matrixL();
  std::normal_distribution<double> normal;
  Eigen::VectorXd z(n);
  for (Eigen::Index i = 0; i < n; ++i) z(i) = normal(rng);
  const Eigen::VectorXd x = l * z;
  return {x.data(), x.data() + n};
}

// Materials by their table names: the two of the vero–DM85 range.
inline mechanics::MaterialTable scaled_materials(const mechanics::MaterialTable& table,
                                                 double vero_ratio, double dm85_ratio) {
  std::vector<mechanics::Material> out = table.materials();
  for (auto& m : out) {
    if (m.name == "VeroClear-Piovarci2018") m.youngs_modulus *= vero_ratio;
    if (m.name == "DM85") m.youngs_modulus *= dm85_ratio;
  }
  mechanics::MaterialTable scaled(std::move(out));
  scaled.set_looked_in(table.looked_in());
  return scaled;
}

inline std::unique_ptr<LoopWorld> make_loop_world(const PredictionInputs& model_inputs,
                                                  const GridAxes& axes, const WorldSpread& spread,
                                                  std::uint64_t seed) {
  auto world = std::make_unique<LoopWorld>();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  const auto& model = model_inputs.model;
  world->truth_model = model;
  for (const auto* material : {&axes.material_a, &axes.material_b}) {
    auto& curve = world->truth_model.material_log_gain.at(*material);
    const auto delta = smooth_random_curve(model.knot_frequencies_hz, spread.curve_sd,
                                           spread.curve_correlation_hz, rng);
    for (std::size_t k = 0; k < curve.size(); ++k) curve[k] += delta[k];
  }
  world->mixing_bow = smooth_random_curve(model.knot_frequencies_hz, spread.curve_sd,
                                          spread.curve_correlation_hz, rng);
  world->vero_modulus_ratio = std::exp(spread.modulus_log_sd * normal(rng));
  world->dm85_modulus_ratio = std::exp(spread.modulus_log_sd * normal(rng));
  world->truth_materials = scaled_materials(model_inputs.setup.materials, world->vero_modulus_ratio,
                                            world->dm85_modulus_ratio);
  world->mu_offset_first = spread.mu_sd * normal(rng);
  world->mu_offset_second = spread.mu_sd * normal(rng);
  world->truth_setup = model_inputs.setup;
  world->truth_setup.model = &world->truth_model;
  world->truth_setup.materials = world->truth_materials;
  world->truth_grid = compute_design_response_grid(world->truth_setup, axes, {}, {}, 0);
  return world;
}

// What the rig would measure of the print of `point`: the truth's spectrum (its response, curves
// and the mix's bow) with the measurement's noise: per cell, and per print a gain and a μ drawn
// from the measurement's descriptor noise R (weighted-mean and μ variances of `noise`, in the
// map's descriptor order: μ first, the log10 weighted mean second).
inline io::Pairing measure_in_world(const LoopWorld& world, const GridAxes& axes,
                                    const DesignPoint& point, const std::string& surface,
                                    const Eigen::MatrixXd& noise, double cell_noise_db,
                                    std::mt19937_64& rng) {
  const double lambda = point.fraction_of(axes.material_b);
  PredictedTool tool =
      predict_from_response(world.truth_setup, point, surface,
                            interpolate_response(world.truth_grid, lambda, point.tip_diameter_m));
  std::normal_distribution<double> normal;
  const double bow = 4 * lambda * (1 - lambda);
  const double gain = std::log(10.0) * std::sqrt(noise(1, 1)) * normal(rng);
  const double cell_sd = cell_noise_db / (20 / std::log(10.0));
  for (std::size_t s = 0; s < tool.spectrum.speeds_m_s.size(); ++s)
    for (std::size_t j = 0; j < tool.spectrum.frequencies_hz.size(); ++j) {
      const double f = tool.spectrum.frequencies_hz[j];
      const double bowed =
          bow * forcing::hermite_value(world.truth_model.knot_frequencies_hz, world.mixing_bow, f);
      tool.spectrum.amplitude_m_s2[s][j] *= std::exp(bowed + gain + cell_sd * normal(rng));
    }
  tool.vibration =
      measure::compute_vibration_descriptors(tool.spectrum, *world.truth_setup.threshold);
  tool.mu += (1 - lambda) * world.mu_offset_first + lambda * world.mu_offset_second +
             std::sqrt(noise(0, 0)) * normal(rng);
  io::Pairing pairing = predicted_pairing(tool, "the catalog's");
  pairing.tool = "print " + to_string(point);
  return pairing;
}

// A loop over the vero–DM85 range on `surface` as the world's tests run it (1,000 draws per
// chance); each test sets its target, rule, rounds and candidates.
inline LoopSetup world_loop_setup(const PredictionInputs& inputs,
                                  std::span<const forcing::ForcingExemplar> exemplars,
                                  const DesignResponseGrid& grid, const space::DescriptorMap& map,
                                  const std::string& surface, double threshold,
                                  const Eigen::MatrixXd& noise) {
  LoopSetup setup;
  setup.inputs = &inputs;
  setup.catalog_exemplars = exemplars;
  setup.grid = &grid;
  setup.map = &map;
  setup.surface = surface;
  setup.range.first_material = "vero";
  setup.range.second_material = "DM85";
  setup.threshold = threshold;
  setup.measurement_noise = noise;
  setup.samples = 1000;
  return setup;
}

}  // namespace nibrig::model::design::test
