// A design moved live by its sliders: what a slider move costs through the design-response
// grid, beside the full prediction it stands in for, at the template's full resolution (3 mm, 64
// modes) and the default grid (5 fractions × 7 tips, vero–DM85, 1-4 mm):
// - DesignGridSliderToPlacement: interpolated |H| and modes, spectrum, μ, descriptors, placement;
// - DesignGridSliderToVoice: the same prediction made into a voice (rt::build_voice), what the
//   panel swaps into its playback session;
// - DesignGridFullPredictTool: predict_tool and placement at the same points (the FEM);
// - DesignGridCompute: the whole grid once, in the background, on every core;
// - DesignGridError: the interpolation's error at every cell centre (counters), not a time.
// The space is the catalog's descriptors (as bench_design): placing costs the same in any space.
#include <benchmark/benchmark.h>

#include <cmath>
#include <optional>

#include "model/design/descriptor_uncertainty.hpp"
#include "model/design/design_grid_error.hpp"
#include "model/design/design_response_grid.hpp"
#include "model/design/design_search.hpp"
#include "model/design/tool_sound.hpp"
#include "model/forcing/catalog_exemplars.hpp"
#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/io/catalog_file.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "rt/engine.hpp"
#include "rt/voice_builder.hpp"
#include "tests/support/test_paths.hpp"

namespace {

using namespace nibrig::model;

struct GridBench {
  io::Catalog catalog;
  mechanics::MaterialTable materials;
  mechanics::Design template_design;
  forcing::ForcingModel model;
  std::optional<measure::ThresholdCurve> threshold;
  design::DescriptorErrorCovariance errors;
  space::DescriptorMap map;
  std::optional<design::DesignResponseGrid> grid;
  design::PredictionSetup setup;  // points into this object, which never moves
};

GridBench& bench() {
  static GridBench* b = [] {
    auto* g = new GridBench;
    const auto assets = nibrig::test::assets_dir();
    g->catalog = io::read_catalog(assets / "default_catalog.json");
    g->materials = mechanics::read_material_table(assets / "materials.json");
    g->template_design =
        mechanics::read_design(assets / "designs" / "stylus_vero_tip2mm.json", g->materials);
    auto exemplars = forcing::select_printed_exemplars(g->catalog).exemplars;
    forcing::attach_responses(exemplars, g->template_design, g->materials);
    g->model = forcing::fit_forcing_model(exemplars);
    g->threshold = measure::ThresholdCurve::load(assets / "thresholds" / "israr2006_pen_hold.csv");
    g->errors = design::descriptor_error_covariance(
        forcing::held_out_descriptor_errors(exemplars, *g->threshold),
        design::friction_interpolation_errors(g->catalog));
    const auto table = space::descriptors_of_catalog(g->catalog, "bundled catalog", 2);
    Eigen::MatrixXd coordinates = table.values.transpose();
    for (Eigen::Index i = 0; i < coordinates.cols(); ++i) coordinates(0, i) += 0.01 * (i % 3);
    g->map = space::fit_descriptor_map(coordinates, table.values, table.names);
    g->setup.model = &g->model;
    g->setup.catalog = &g->catalog;
    g->setup.template_design = g->template_design;
    g->setup.materials = g->materials;
    g->setup.threshold = &*g->threshold;
    g->setup.descriptor_errors = &g->errors;
    return g;
  }();
  return *b;
}

design::GridAxes default_axes() {
  return design::even_axes("vero", "DM85", design::kDefaultFractionPoints, 0.001, 0.004,
                           design::kDefaultTipPoints);
}

const design::DesignResponseGrid& grid() {
  auto& b = bench();
  if (!b.grid) b.grid = design::compute_design_response_grid(b.setup, default_axes());
  return *b.grid;
}

// A slider sweeping the range off the nodes: the k-th move's (λ, tip).
std::pair<double, double> slider(std::size_t k) {
  const double s = std::fmod(0.0137 + 0.618034 * static_cast<double>(k), 1.0);
  const double t = std::fmod(0.0291 + 0.414214 * static_cast<double>(k), 1.0);
  return {s, 0.001 + 0.003 * t};
}

void BM_DesignGridSliderToPlacement(benchmark::State& state) {
  auto& b = bench();
  const auto& g = grid();
  std::size_t k = 0;
  double x = 0;
  for (auto _ : state) {
    const auto [fraction, tip] = slider(k++);
    const auto tool = design::predict_from_grid(b.setup, g, fraction, tip, "office");
    const auto placement = design::place_predicted(b.map, tool);
    x += placement.mean(0);
  }
  benchmark::DoNotOptimize(x);
  state.counters["nodes"] = static_cast<double>(g.nodes.size());
  state.counters["budget_ms"] = 50;
}
BENCHMARK(BM_DesignGridSliderToPlacement)->Unit(benchmark::kMillisecond);

void BM_DesignGridSliderToVoice(benchmark::State& state) {
  auto& b = bench();
  const auto& g = grid();
  const double rate = nibrig::rt::internal_rate_for(nibrig::rt::EngineSettings{});
  std::size_t k = 0;
  for (auto _ : state) {
    const auto [fraction, tip] = slider(k++);
    auto sound = design::predicted_sound(design::predict_from_grid(b.setup, g, fraction, tip, "office"));
    auto voice = nibrig::rt::build_voice(sound, rate, k);
    benchmark::DoNotOptimize(voice.get());
  }
  state.counters["modes"] = g.modes;
  state.counters["budget_ms"] = 50;
}
BENCHMARK(BM_DesignGridSliderToVoice)->Unit(benchmark::kMillisecond);

void BM_DesignGridFullPredictTool(benchmark::State& state) {
  auto& b = bench();
  std::size_t k = 0;
  for (auto _ : state) {
    const auto [fraction, tip] = slider(k++);
    const auto tool = design::predict_tool(b.setup, design::grid_point(default_axes(), fraction, tip),
                                           "office");
    benchmark::DoNotOptimize(design::place_predicted(b.map, tool).mean(0));
  }
}
BENCHMARK(BM_DesignGridFullPredictTool)->Iterations(3)->Unit(benchmark::kMillisecond);

void BM_DesignGridCompute(benchmark::State& state) {
  auto& b = bench();
  std::size_t nodes = 0;
  for (auto _ : state)
    nodes = design::compute_design_response_grid(b.setup, default_axes()).nodes.size();
  state.counters["nodes"] = static_cast<double>(nodes);
}
BENCHMARK(BM_DesignGridCompute)->Iterations(1)->Unit(benchmark::kSecond);

void BM_DesignGridError(benchmark::State& state) {
  auto& b = bench();
  const auto& g = grid();
  design::GridError e;
  for (auto _ : state) e = design::measure_grid_error(b.setup, g, "office", 2, &b.map);
  double mean_rms = 0;
  for (const auto& c : e.cells) mean_rms += c.response_rms_db / static_cast<double>(e.cells.size());
  state.counters["cells"] = static_cast<double>(e.cells.size());
  state.counters["H_rms_db_worst"] = e.response_rms_db;
  state.counters["H_rms_db_mean"] = mean_rms;
  state.counters["H_max_db"] = e.response_max_db;
  state.counters["modes_H_rms_db_worst"] = e.modal_response_rms_db;
  state.counters["log10_wm_err"] = e.descriptor_error[1];
  state.counters["log10_wm_cv_sd"] = e.cross_validated_sd[1];
  state.counters["placement_err"] = e.placement_distance;
  state.counters["placement_sd"] = e.placement_sd;
  state.counters["mode_jumps"] = static_cast<double>(g.mode_jumps);
}
BENCHMARK(BM_DesignGridError)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
