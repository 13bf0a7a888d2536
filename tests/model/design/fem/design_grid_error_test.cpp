// The design-response grid against the real FEM, on the bundled catalog's forcing model:
// predict_tool split in two gives what it gave whole, the interpolation's error at cell centres is
// small and shrinks when the grid is refined, and a search guided by the grid finds the full
// search's optimum for fewer solves. The designs use 32 modes on a 4 mm mesh (as the held-out tip
// test: |H| within ~1 % of the full template's) so that the solves (21 s in all in Release) stay
// short; the grid's error at the panel's full resolution and default density is measured by the
// benchmark DesignGridError (tests/bench/bench_design_grid.cpp), the guided search's by
// DesignLineSearchGuided.
//
// The space is the catalog's descriptors themselves (coordinates = μ and log10 weighted mean, as
// in bench_design): a placement error in it is a descriptor error in descriptor units, so the
// bound on it is the same argument as on the descriptors.
#include "model/design/design_grid_error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "model/design/descriptor_uncertainty.hpp"
#include "model/design/design_response_grid.hpp"
#include "model/design/design_search.hpp"
#include "model/design/grid_guided_search.hpp"
#include "model/forcing/catalog_exemplars.hpp"
#include "model/forcing/forcing_fit.hpp"
#include "model/forcing/leave_one_out.hpp"
#include "model/io/catalog_file.hpp"
#include "model/mechanics/material_table.hpp"
#include "model/mechanics/stylus_description.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

constexpr double kMeshSize = 0.004;
constexpr int kModes = 32;

struct RealSetup {
  io::Catalog catalog;
  forcing::ForcingModel model;
  measure::ThresholdCurve threshold;
  DescriptorErrorCovariance errors;
  PredictionSetup setup;
};

const RealSetup& real() {
  static const RealSetup r = [] {
    const auto assets = nibrig::test::assets_dir();
    RealSetup s{io::read_catalog(assets / "default_catalog.json"),
                {},
                measure::ThresholdCurve::load(assets / "thresholds" / "israr2006_pen_hold.csv"),
                {},
                {}};
    s.setup.materials = mechanics::read_material_table(assets / "materials.json");
    s.setup.template_design =
        mechanics::read_design(assets / "designs" / "stylus_vero_tip2mm.json", s.setup.materials);
    auto exemplars = forcing::select_printed_exemplars(s.catalog).exemplars;
    forcing::attach_responses(exemplars, s.setup.template_design, s.setup.materials,
                              {kMeshSize, kModes});
    s.model = forcing::fit_forcing_model(exemplars);
    s.errors = descriptor_error_covariance(
        forcing::held_out_descriptor_errors(exemplars, s.threshold),
        friction_interpolation_errors(s.catalog));
    s.setup.mesh_size = kMeshSize;
    s.setup.modes = kModes;
    return s;
  }();
  return r;
}

// The setup's pointers are set here, into the static RealSetup, which never moves.
PredictionSetup setup_of(const RealSetup& r) {
  PredictionSetup setup = r.setup;
  setup.model = &r.model;
  setup.catalog = &r.catalog;
  setup.threshold = &r.threshold;
  setup.descriptor_errors = &r.errors;
  return setup;
}

// vero–DM85, λ ∈ {0, 0.5, 1} × tip ∈ {1, 2.5, 4} mm.
const DesignResponseGrid& real_grid() {
  static const DesignResponseGrid grid = [] {
    std::size_t calls = 0, last_total = 0;
    auto g = compute_design_response_grid(
        setup_of(real()), GridAxes{"vero", "DM85", {0.0, 0.5, 1.0}, {0.001, 0.0025, 0.004}},
        [&](std::size_t done, std::size_t total) {
          ++calls;
          EXPECT_EQ(done, calls);
          last_total = total;
        });
    EXPECT_EQ(calls, 9u);  // one call per node, counted in order
    EXPECT_EQ(last_total, 9u);
    return g;
  }();
  return grid;
}

space::DescriptorMap descriptor_space(const io::Catalog& catalog) {
  const auto table = space::descriptors_of_catalog(catalog, "bundled catalog", 2);
  Eigen::MatrixXd coordinates = table.values.transpose();
  // A little scatter so that the map's residual covariance is not singular.
  for (Eigen::Index i = 0; i < coordinates.cols(); ++i) coordinates(0, i) += 0.01 * (i % 3);
  return space::fit_descriptor_map(coordinates, table.values, table.names);
}

// The catalog's vero4 on office, placed in `map` from its descriptors: the searches' target.
space::Placement vero4_office(const space::DescriptorMap& map) {
  const auto table = space::descriptors_of_catalog(real().catalog, "bundled catalog", 2);
  const auto row =
      std::find(table.rows.begin(), table.rows.end(), "vero4/office") - table.rows.begin();
  if (static_cast<std::size_t>(row) >= table.rows.size())
    throw std::runtime_error("no vero4/office in the catalog");
  return space::place_from_descriptors(map, table.values.row(row).transpose());
}

TEST(DesignGridFem, PredictToolInTwoStepsIsPredictToolWhole) {
  const PredictionSetup setup = setup_of(real());
  const DesignPoint point = grid_point(real_grid().axes, 0.5, 0.0025);
  const PredictedTool whole = predict_tool(setup, point, "office");
  // The grid's node at this point was solved by simulate_response: the same FEM, deterministic.
  const PredictedTool split =
      predict_from_response(setup, point, "office", real_grid().node(1, 1));
  EXPECT_EQ(split.response_magnitude, whole.response_magnitude);
  EXPECT_EQ(split.modal.omega, whole.modal.omega);
  EXPECT_EQ(split.spectrum.amplitude_m_s2, whole.spectrum.amplitude_m_s2);
  EXPECT_EQ(split.vibration.weighted_mean, whole.vibration.weighted_mean);
  EXPECT_EQ(split.mu, whole.mu);
  EXPECT_EQ(split.design_name, whole.design_name);
  EXPECT_EQ(split.descriptor_errors.covariance, whole.descriptor_errors.covariance);
}

TEST(DesignGridFem, InterpolationErrorAtCellCentresIsSmallAndShrinksAsTheGridRefines) {
  const PredictionSetup setup = setup_of(real());
  const DesignResponseGrid& fine = real_grid();
  const space::DescriptorMap map = descriptor_space(real().catalog);
  const GridError error = measure_grid_error(setup, fine, "office", 2, &map);
  ASSERT_EQ(error.cells.size(), 4u);
  for (const auto& c : error.cells)
    std::printf(
        "cell centre λ %.2f tip %.2f mm: |H| %.3f dB rms (%.2f max), modes' |H| %.3f dB rms, "
        "ω1 %+.2e, Δμ %+.1e Δlog10 wm %+.1e, placement %.2e (sd %.3f)\n",
        c.fraction, c.tip_m * 1e3, c.response_rms_db, c.response_max_db, c.modal_response_rms_db,
        c.first_mode_error, c.descriptor_error[0], c.descriptor_error[1], c.placement_distance,
        c.placement_sd);
  ASSERT_EQ(error.cross_validated_sd.size(), 2u);
  std::printf("worst: |H| %.3f dB rms, log10 wm %.2e against a cross-validated sd of %.3f\n",
              error.response_rms_db, error.descriptor_error[1], error.cross_validated_sd[1]);

  // μ is not interpolated through the grid at all: both paths take it from the catalog.
  EXPECT_EQ(error.descriptor_error[0], 0.0);
  // The bound: a tenth of the predictions' own cross-validated error of the weighted mean (the
  // descriptor the 2-D space follows). An interpolation error that small adds 0.5 % to the
  // prediction's variance: no listener could tell the grid's point from the FEM's.
  EXPECT_LT(error.descriptor_error[1], 0.1 * error.cross_validated_sd[1]);
  // In the space the same tenth, of the placement's own uncertainty.
  EXPECT_LT(error.placement_distance, 0.1 * error.placement_sd);
  // |H|: under 1 dB rms, less than half the 2.3 dB by which two measurements of one print differ.
  EXPECT_LT(error.response_rms_db, 1.0);

  // The coarse grid of the fine one's corners (steps twice as long), at the same cell centres: the
  // error must shrink where the response is smooth in (λ, tip), bilinear interpolation's error
  // going as the step squared. Compared on the mean over the four centres, in dB rms of |H|.
  DesignResponseGrid coarse = fine;
  coarse.axes.fractions = {0.0, 1.0};
  coarse.axes.tips_m = {0.001, 0.004};
  coarse.nodes = {fine.node(0, 0), fine.node(0, 2), fine.node(2, 0), fine.node(2, 2)};
  std::vector<std::pair<double, double>> centres;
  for (const auto& c : error.cells) centres.emplace_back(c.fraction, c.tip_m);
  const GridError coarse_error = measure_grid_error_at(setup, coarse, centres, "office", 2, &map);
  double fine_mean = 0, coarse_mean = 0;
  for (std::size_t k = 0; k < centres.size(); ++k) {
    fine_mean += error.cells[k].response_rms_db / centres.size();
    coarse_mean += coarse_error.cells[k].response_rms_db / centres.size();
  }
  std::printf("mean |H| error at the 3×3 grid's cell centres: %.3f dB rms; from its corners alone "
              "(2×2): %.3f dB rms; weighted mean %.2e vs %.2e\n",
              fine_mean, coarse_mean, error.descriptor_error[1], coarse_error.descriptor_error[1]);
  EXPECT_LT(fine_mean, coarse_mean);
  EXPECT_LT(error.descriptor_error[1], coarse_error.descriptor_error[1]);
}

}  // namespace
}  // namespace nibrig::model::design

namespace nibrig::model::design {
namespace {

// A search through the grid's predictor: at the grid's nodes (FEM-solved) a candidate is the FEM
// search's candidate; between them it is within the interpolation's error of it. The target is
// the catalog's vero4 on office, placed in the descriptor space.
TEST(DesignGridFem, ASearchThroughTheGridEvaluatesNodesAsTheFemSearchDoes) {
  const PredictionSetup setup = setup_of(real());
  const space::DescriptorMap map = descriptor_space(real().catalog);
  const space::Placement target = vero4_office(map);
  const Evaluate on_grid = distance_to_target(grid_predictor(setup, real_grid(), "office"), map, target, 500);
  const Evaluate by_fem = distance_to_target(setup, "office", map, target, 500);
  const DesignPoint node = grid_point(real_grid().axes, 0.5, 0.0025);
  const Candidate a = on_grid(node), b = by_fem(node);
  EXPECT_NEAR(a.distance, b.distance, 1e-12);  // the same FEM response at a node
  EXPECT_NEAR(a.mu, b.mu, 1e-12);
  // A design mixing a material the grid does not hold is refused by name.
  try {
    on_grid(parse_design_point("vero:0.5,steel:0.5,tip=2mm"));
    FAIL() << "a material outside the grid was predicted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("steel"), std::string::npos) << e.what();
  }
  // The whole line search along the mix at 2.5 mm through the grid, milliseconds a candidate.
  const SearchResult line = line_search(grid_point(real_grid().axes, 0.0, 0.0025),
                                        grid_point(real_grid().axes, 1.0, 0.0025), on_grid);
  EXPECT_GE(line.evaluated.size(), 9u);
  EXPECT_TRUE(std::isfinite(line.best().distance));
}

}  // namespace
}  // namespace nibrig::model::design

namespace nibrig::model::design {
namespace {

// The guided search against the full one, along the diagonal vero at 1 mm → DM85 at 4 mm (through
// every cell of the 3 × 3 grid) to the catalog's vero4 on office.
TEST(DesignGridFem, AGuidedSearchFindsTheFullSearchsOptimumWithinTheGridsErrorWithFewerSolves) {
  const PredictionSetup setup = setup_of(real());
  const space::DescriptorMap map = descriptor_space(real().catalog);
  const space::Placement target = vero4_office(map);
  const Evaluate by_fem = distance_to_target(setup, "office", map, target, 500);
  const DesignPoint a = parse_design_point("vero,tip=1mm"), b = parse_design_point("DM85,tip=4mm");

  const SearchResult full = line_search(a, b, by_fem);
  const SearchResult on_grid = line_search(
      a, b, distance_to_target(grid_predictor(setup, real_grid(), "office"), map, target, 500));
  const GuidedSearch guided = guide_by_fem(on_grid, setup, real_grid(), "office", map, by_fem);
  std::printf(
      "full: %zu solves, optimum %s at %.4f; guided: %zu solves (%zu checks), ε %.2e, "
      "optimum %s at %.4f\n",
      full.evaluated.size(), to_string(full.best().point).c_str(), full.best().distance,
      guided.fem_solves, guided.checks.size(), guided.grid_error,
      to_string(guided.result.best().point).c_str(), guided.result.best().distance);

  // The rule, checked from the grid search's own numbers: the contenders are exactly the grid's
  // candidates within 2ε of its best, and the optimum is one of them.
  double best_on_grid = on_grid.best().distance;
  for (std::size_t k = 0; k < on_grid.evaluated.size(); ++k)
    EXPECT_EQ(guided.fem_solved[k],
              on_grid.evaluated[k].distance <= best_on_grid + 2 * guided.grid_error)
        << "candidate " << k;
  EXPECT_TRUE(guided.fem_solved[guided.result.ranked.front()]);
  // A solved candidate's numbers are the FEM's own, bit for bit.
  const std::size_t best = guided.result.ranked.front();
  EXPECT_EQ(guided.result.best().distance, by_fem(on_grid.evaluated[best].point).distance);
  ASSERT_FALSE(guided.checks.empty());
  EXPECT_GT(guided.grid_error,
            0.0);  // a cell centre is never a node: the grid is never exact there

  // The claim: within the grid's measured error of the full search's optimum, for fewer FEM solves.
  EXPECT_NEAR(guided.result.best().distance, full.best().distance, guided.grid_error);
  EXPECT_LT(guided.fem_solves, full.evaluated.size());
}

}  // namespace
}  // namespace nibrig::model::design
