// Cost of the forcing model and of design by search: simulating the nine printed
// designs' responses, the fit of Eq. 10 plus the leave-one-out over the paper's tools, and one line
// search (every candidate meshed, solved and predicted at the template's full resolution, 3 mm and
// 64 modes). The space of the search is made from the catalog's descriptors (as in
// design_cli_test): its cost does not depend on how the space was fitted.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>

#include "model/design/bundled_defaults.hpp"
#include "model/design/descriptor_uncertainty.hpp"
#include "model/design/design_search.hpp"
#include "model/design/grid_guided_search.hpp"
#include "model/design/interpolation_check.hpp"
#include "model/design/material_hold_out.hpp"
#include "model/forcing/catalog_exemplars.hpp"
#include "model/forcing/curve_jackknife.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/io/catalog_file.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "tests/support/test_paths.hpp"

namespace {

using namespace nibrig::model;

struct Inputs {
  io::Catalog catalog;
  mechanics::MaterialTable materials;
  mechanics::Design template_design;
  std::vector<forcing::ForcingExemplar> exemplars;
};

Inputs& inputs(bool with_responses) {
  static Inputs in = [] {
    const auto assets = nibrig::test::assets_dir();
    Inputs i;
    i.catalog = io::read_catalog(assets / "default_catalog.json");
    i.materials = mechanics::read_material_table(assets / "materials.json");
    i.template_design =
        mechanics::read_design(assets / "designs" / "stylus_vero_tip2mm.json", i.materials);
    i.exemplars = forcing::select_printed_exemplars(i.catalog).exemplars;
    return i;
  }();
  if (with_responses && in.exemplars.front().response_magnitude.empty())
    forcing::attach_responses(in.exemplars, in.template_design, in.materials);
  return in;
}

void BM_ForcingDesignResponses(benchmark::State& state) {
  auto& in = inputs(false);
  std::size_t designs = 0;
  for (auto _ : state) {
    auto exemplars = in.exemplars;
    designs = forcing::attach_responses(exemplars, in.template_design, in.materials).size();
  }
  state.counters["designs"] = static_cast<double>(designs);
}
BENCHMARK(BM_ForcingDesignResponses)->Iterations(1)->Unit(benchmark::kSecond);

void BM_ForcingFitAndLeaveOneOut(benchmark::State& state) {
  auto& in = inputs(true);
  std::vector<std::size_t> paper;
  for (std::size_t e = 0; e < in.exemplars.size(); ++e)
    if (forcing::is_paper_tool(in.exemplars[e])) paper.push_back(e);
  double mean_db = 0;
  for (auto _ : state) {
    const auto model = forcing::fit_forcing_model(in.exemplars);
    benchmark::DoNotOptimize(model.residual_rms_db);
    mean_db = forcing::leave_one_out(in.exemplars, paper).summary.mean_rms_db;
  }
  state.counters["exemplars"] = static_cast<double>(in.exemplars.size());
  state.counters["held_out"] = static_cast<double>(paper.size());
  state.counters["loo_mean_db"] = mean_db;
}
BENCHMARK(BM_ForcingFitAndLeaveOneOut)->Iterations(3)->Unit(benchmark::kMillisecond);

// The curves' standard errors (one refit per printed tool), the 2 mm and the DM95 hold-outs with
// what the data resolve: what `nibrig forcing fit` and `forcing holdout` add to the fit.
void BM_ForcingJackknifeAndHoldout(benchmark::State& state) {
  auto& in = inputs(true);
  std::size_t tools = 0, resolved = 0;
  for (auto _ : state) {
    const auto jackknife = forcing::jackknife_curves(in.exemplars);
    tools = jackknife.replicates.size();
    benchmark::DoNotOptimize(design::hold_out_tip(in.exemplars, 0.002).predictions.size());
    resolved = design::tip_resolution(jackknife, 0.002).effect_resolved_knots();
    const double f = design::equal_modulus_fraction(in.materials, "DM95", "vero", "DM85");
    benchmark::DoNotOptimize(
        design::hold_out_material(in.exemplars, "DM95", "vero", "DM85", f).predictions.size());
    benchmark::DoNotOptimize(
        design::material_resolution(jackknife, "DM95", "vero", "DM85", f).fitted_fraction);
  }
  state.counters["tools"] = static_cast<double>(tools);
  state.counters["tip_effect_knots_resolved"] = static_cast<double>(resolved);
}
BENCHMARK(BM_ForcingJackknifeAndHoldout)->Iterations(3)->Unit(benchmark::kMillisecond);

// What a fit adds so that predicted tools carry their error: every exemplar held out in turn and
// its descriptors compared (54 refits), and the covariance with the catalog's friction errors.
void BM_ForcingHeldOutDescriptorErrors(benchmark::State& state) {
  auto& in = inputs(true);
  const auto threshold = measure::ThresholdCurve::load(nibrig::test::assets_dir() / "thresholds" /
                                                       "israr2006_pen_hold.csv");
  double weighted_mean_sd = 0;
  std::size_t held_out = 0;
  for (auto _ : state) {
    const auto errors = forcing::held_out_descriptor_errors(in.exemplars, threshold);
    const auto covariance = design::descriptor_error_covariance(
        errors, design::friction_interpolation_errors(in.catalog));
    held_out = errors.size();
    weighted_mean_sd = std::sqrt(covariance.block(space::paper_descriptor_names(2))(1, 1));
  }
  state.counters["held_out"] = static_cast<double>(held_out);
  state.counters["weighted_mean_sd_log10"] = weighted_mean_sd;
}
BENCHMARK(BM_ForcingHeldOutDescriptorErrors)->Iterations(3)->Unit(benchmark::kMillisecond);

// The line search's world: the catalog's forcing model, a space of its descriptors, the target
// cryon/office's place in it, the setup predicting at the template's full resolution.
struct LineSearchWorld {
  forcing::ForcingModel model;
  space::DescriptorMap map;
  space::Placement target;
  measure::ThresholdCurve threshold = measure::ThresholdCurve::load(
      nibrig::test::assets_dir() / "thresholds" / "israr2006_pen_hold.csv");
  design::DescriptorErrorCovariance errors;
  design::DesignPoint a = design::parse_design_point("vero,tip=1mm"),
                      b = design::parse_design_point("DM85,tip=4mm");
};

const LineSearchWorld& line_search_world() {
  static const LineSearchWorld w = [] {
    auto& in = inputs(true);
    LineSearchWorld w;
    w.model = forcing::fit_forcing_model(in.exemplars);
    const std::vector<std::string> stimuli{"cryon/office", "stab/office",  "vero1/office",
                                           "vero4/office", "DM854/office", "vero1/glass",
                                           "DM851/glass",  "vero4/glass"};
    const auto table = space::descriptors_for_stimuli(in.catalog, "bundled catalog", stimuli, 2);
    Eigen::MatrixXd coordinates = table.values.transpose();
    for (Eigen::Index i = 0; i < coordinates.cols(); ++i) coordinates(0, i) += 0.01 * (i % 3);
    w.map = space::fit_descriptor_map(coordinates, table.values, table.names);
    w.target = space::Placement{coordinates.col(0), Eigen::MatrixXd::Zero(2, 2)};
    w.errors = design::descriptor_error_covariance(
        forcing::held_out_descriptor_errors(in.exemplars, w.threshold),
        design::friction_interpolation_errors(in.catalog));
    return w;
  }();
  return w;
}

design::PredictionSetup line_search_setup(const LineSearchWorld& w) {
  auto& in = inputs(true);
  design::PredictionSetup setup;
  setup.model = &w.model;
  setup.catalog = &in.catalog;
  setup.template_design = in.template_design;
  setup.materials = in.materials;
  setup.threshold = &w.threshold;
  setup.descriptor_errors = &w.errors;
  return setup;
}

void BM_DesignLineSearch(benchmark::State& state) {
  const auto& w = line_search_world();
  const auto setup = line_search_setup(w);
  std::size_t predictions = 0;
  for (auto _ : state) {
    const auto result = design::line_search(
        w.a, w.b, design::distance_to_target(setup, "protector", w.map, w.target));
    predictions = result.evaluated.size();
  }
  state.counters["predictions"] = static_cast<double>(predictions);
}
BENCHMARK(BM_DesignLineSearch)->Iterations(1)->Unit(benchmark::kSecond);

// The same search through the default design grid (5 × 7 nodes over vero-DM85 × 1-4 mm, solved
// before the timing as the cache holds it), the FEM solved only where the grid's error could change
// the answer (grid_guided_search.hpp). Beside it, in the same run: the full search's optimum, and
// how far the guided one is from it against the grid's measured error.
void BM_DesignLineSearchGuided(benchmark::State& state) {
  const auto& w = line_search_world();
  const auto setup = line_search_setup(w);
  const auto grid = design::compute_design_response_grid(
      setup, design::even_axes("vero", "DM85", design::kDefaultFractionPoints, 0.001, 0.004,
                               design::kDefaultTipPoints));
  const auto by_fem = design::distance_to_target(setup, "protector", w.map, w.target);
  const auto full_start = std::chrono::steady_clock::now();
  const auto full = design::line_search(w.a, w.b, by_fem);
  const double full_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - full_start).count();
  design::GuidedSearch guided;
  for (auto _ : state) {
    const auto on_grid =
        design::line_search(w.a, w.b,
                            design::distance_to_target(
                                design::grid_predictor(setup, grid, "protector"), w.map, w.target));
    guided = design::guide_by_fem(on_grid, setup, grid, "protector", w.map, by_fem);
  }
  state.counters["fem_solves"] = static_cast<double>(guided.fem_solves);
  state.counters["full_predictions"] = static_cast<double>(full.evaluated.size());
  state.counters["full_s"] = full_seconds;
  state.counters["grid_error"] = guided.grid_error;
  state.counters["optimum_gap"] = std::abs(guided.result.best().distance - full.best().distance);
}
BENCHMARK(BM_DesignLineSearchGuided)->Iterations(1)->Unit(benchmark::kSecond);

// A first start on the bundled inputs with an empty user cache: everything the panel and the
// commands would compute (compute_bundled_defaults), read from the layer the build computed
// (`shipped:1`) beside computed as a first start did before it (`shipped:0`, the layer switched
// off).
void BM_BundledDefaultsFirstStart(benchmark::State& state) {
  const bool shipped = state.range(0) != 0;
  const auto cache = nibrig::test::scratch_dir("bench_first_start") / "cache";
  std::optional<nibrig::test::ScopedEnvironment> no_layer;
  if (!shipped) no_layer.emplace("NIBRIG_SHIPPED_CACHE", "");
  const nibrig::test::ScopedCacheDir user(cache);
  std::size_t computed = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::filesystem::remove_all(cache);
    state.ResumeTiming();
    computed = 0;
    for (const auto& d : design::compute_bundled_defaults()) computed += d.computed;
  }
  state.counters["computed"] = static_cast<double>(computed);
}
BENCHMARK(BM_BundledDefaultsFirstStart)
    ->ArgName("shipped")
    ->Arg(1)
    ->Arg(0)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace
