// The coarse grid first: coarse_axes keeps every other node of the fine grid (both ends); a fine
// grid solved with the coarse grid's nodes `known` is the fine grid solved whole, counting only the
// nodes it solves; cached_design_response_grid hands the coarse grid to on_coarse before it solves
// the rest, not at all when the fine grid is cached, and a stop in either phase writes nothing of
// the grid stopped. The FEM runs on the hand-made forcing model's five frequencies with 8 modes on
// a 4 mm mesh (no fit): a 3 × 3 grid (coarse 2 × 2) takes seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "model/design/design_grid_file.hpp"
#include "model/design/design_response_grid.hpp"
#include "model/numeric/cancellation.hpp"
#include "tests/model/design/hand_made_forcing_model.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

// The prediction inputs of the hand-made model (tips fitted at 1, 2 and 4 mm), solved coarsely.
std::unique_ptr<PredictionInputs> coarse_grid_test_inputs() {
  forcing::ForcingInputOptions options;
  options.catalog = nibrig::test::assets_dir() / "default_catalog.json";
  options.mesh_size = 0.004;
  options.modes = 8;
  return load_prediction_inputs(options, "", hand_made_model());
}

// vero–DM85, λ ∈ {0, 0.5, 1} × tip ∈ {1, 2.5, 4} mm; its coarse grid is the four corners.
GridAxes coarse_test_fine_axes() { return even_axes("vero", "DM85", 3, 0.001, 0.004, 3); }

bool coarse_test_grid_cached(const PredictionInputs& inputs, const GridAxes& axes) {
  return std::filesystem::exists(design_grid_cache_file(design_grid_cache_key(inputs, axes)));
}

// Node by node, bit for bit: a node copied is the solve it was copied from, and one design solved
// twice is the same solve (Gmsh's mesh, the assembly and the eigensolve are deterministic:
// DesignGridFem.PredictToolInTwoStepsIsPredictToolWhole holds them to equality too).
void expect_same_coarse_test_nodes(const DesignResponseGrid& a, const DesignResponseGrid& b) {
  EXPECT_EQ(a.axes.fractions, b.axes.fractions);
  EXPECT_EQ(a.axes.tips_m, b.axes.tips_m);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t n = 0; n < a.nodes.size(); ++n) {
    EXPECT_EQ(a.nodes[n].design_name, b.nodes[n].design_name) << "node " << n;
    EXPECT_EQ(a.nodes[n].response_magnitude, b.nodes[n].response_magnitude) << "node " << n;
    EXPECT_EQ(a.nodes[n].modal.omega, b.nodes[n].modal.omega) << "node " << n;
    EXPECT_EQ(a.nodes[n].modal.zeta, b.nodes[n].modal.zeta) << "node " << n;
    EXPECT_EQ(a.nodes[n].modal.input, b.nodes[n].modal.input) << "node " << n;
    EXPECT_EQ(a.nodes[n].modal.output, b.nodes[n].modal.output) << "node " << n;
  }
  EXPECT_EQ(a.mode_jumps, b.mode_jumps);
}

// The coarse grid's nodes inside the fine one: each where its (fraction, tip) is, bit for bit.
void expect_coarse_nodes_in_fine(const DesignResponseGrid& coarse, const DesignResponseGrid& fine) {
  const auto& f = fine.axes;
  for (std::size_t i = 0; i < coarse.axes.fractions.size(); ++i)
    for (std::size_t j = 0; j < coarse.axes.tips_m.size(); ++j) {
      const auto fi = std::find(f.fractions.begin(), f.fractions.end(), coarse.axes.fractions[i]);
      const auto fj = std::find(f.tips_m.begin(), f.tips_m.end(), coarse.axes.tips_m[j]);
      ASSERT_NE(fi, f.fractions.end());
      ASSERT_NE(fj, f.tips_m.end());
      const auto& node = fine.node(fi - f.fractions.begin(), fj - f.tips_m.begin());
      EXPECT_EQ(node.response_magnitude, coarse.node(i, j).response_magnitude);
      EXPECT_EQ(node.modal.omega, coarse.node(i, j).modal.omega);
      EXPECT_EQ(node.modal.output, coarse.node(i, j).modal.output);
    }
}

TEST(CoarseAxes, KeepBothEndsAndEveryOtherNodeOfTheFineGrid) {
  const GridAxes fine =
      even_axes("vero", "DM85", kDefaultFractionPoints, 0.001, 0.004, kDefaultTipPoints);
  const GridAxes coarse = coarse_axes(fine);
  EXPECT_EQ(coarse.material_a, "vero");
  EXPECT_EQ(coarse.material_b, "DM85");
  // 5 × 7 → 3 × 4, the same doubles as the fine nodes (not recomputed: == on doubles).
  EXPECT_EQ(coarse.fractions,
            (std::vector<double>{fine.fractions[0], fine.fractions[2], fine.fractions[4]}));
  EXPECT_EQ(coarse.fractions, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(coarse.tips_m,
            (std::vector<double>{fine.tips_m[0], fine.tips_m[2], fine.tips_m[4], fine.tips_m[6]}));
  EXPECT_EQ(coarse.tips_m.front(), 0.001);
  EXPECT_EQ(coarse.tips_m.back(), 0.004);
  EXPECT_EQ(coarse.fractions.size() * coarse.tips_m.size(), 12u);
  for (double f : coarse.fractions)
    EXPECT_NE(std::find(fine.fractions.begin(), fine.fractions.end(), f), fine.fractions.end())
        << f;
  for (double t : coarse.tips_m)
    EXPECT_NE(std::find(fine.tips_m.begin(), fine.tips_m.end(), t), fine.tips_m.end()) << t;
  EXPECT_NO_THROW(validate(coarse));

  // 2 × 2 stays; 3 × 3 keeps its ends.
  const GridAxes two = even_axes("vero", "DM85", 2, 0.001, 0.004, 2);
  EXPECT_EQ(coarse_axes(two).fractions, two.fractions);
  EXPECT_EQ(coarse_axes(two).tips_m, two.tips_m);
  const GridAxes three = coarse_test_fine_axes();
  EXPECT_EQ(coarse_axes(three).fractions, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(coarse_axes(three).tips_m, (std::vector<double>{0.001, 0.004}));
  // An even count: n/2 + 1 nodes, the inner ones nearest an even spread (indices 0 2 3 of 4,
  // 0 2 3 5 of 6).
  const GridAxes even_counts = even_axes("vero", "DM85", 4, 0.001, 0.004, 6);
  const GridAxes coarse_even = coarse_axes(even_counts);
  EXPECT_EQ(coarse_even.fractions,
            (std::vector<double>{even_counts.fractions[0], even_counts.fractions[2],
                                 even_counts.fractions[3]}));
  EXPECT_EQ(coarse_even.tips_m,
            (std::vector<double>{even_counts.tips_m[0], even_counts.tips_m[2],
                                 even_counts.tips_m[3], even_counts.tips_m[5]}));
  // Axes validate refuses are refused here too.
  EXPECT_THROW(coarse_axes(GridAxes{"vero", "DM85", {0.0}, {0.001, 0.002}}), std::invalid_argument);
}

TEST(CoarseGridFem, AFineGridFromItsCoarseNodesIsTheFineGridSolvedWhole) {
  const auto inputs = coarse_grid_test_inputs();
  const GridAxes fine_axes = coarse_test_fine_axes();
  const auto coarse = compute_design_response_grid(inputs->setup, coarse_axes(fine_axes));
  ASSERT_EQ(coarse.nodes.size(), 4u);

  std::vector<std::size_t> done_seen, totals_seen;
  const auto reused = compute_design_response_grid(
      inputs->setup, fine_axes,
      [&](std::size_t done, std::size_t total) {
        done_seen.push_back(done);
        totals_seen.push_back(total);
      },
      {}, 0, &coarse);
  // Only the 9 − 4 nodes solved are counted, once each, in order.
  EXPECT_EQ(done_seen, (std::vector<std::size_t>{1, 2, 3, 4, 5}));
  EXPECT_EQ(totals_seen, std::vector<std::size_t>(5, 5));

  const auto whole = compute_design_response_grid(inputs->setup, fine_axes);
  expect_same_coarse_test_nodes(reused, whole);
  expect_coarse_nodes_in_fine(coarse, reused);

  // A known grid that is the whole grid: nothing to solve, nothing counted, the same grid.
  std::size_t calls = 0;
  const auto all_known = compute_design_response_grid(
      inputs->setup, fine_axes, [&](std::size_t, std::size_t) { ++calls; }, {}, 0, &whole);
  EXPECT_EQ(calls, 0u);
  expect_same_coarse_test_nodes(all_known, whole);

  // A known grid solved otherwise (another mesh size) is not the same solve: all 9 are to solve.
  // The first node counted stops it, so that only the total is paid for.
  DesignResponseGrid other_mesh = coarse;
  other_mesh.mesh_size_m *= 2;
  std::stop_source stop;
  std::size_t total_other = 0;
  EXPECT_THROW(compute_design_response_grid(
                   inputs->setup, fine_axes,
                   [&](std::size_t, std::size_t total) {
                     total_other = total;
                     stop.request_stop();
                   },
                   stop.get_token(), 0, &other_mesh),
               numeric::Cancelled);
  EXPECT_EQ(total_other, 9u);
}

TEST(CoarseGridCache, OnCoarseComesOnceBeforeTheFineGridAndNotWhenItIsCached) {
  const nibrig::test::ScopedCacheDir cache(nibrig::test::scratch_dir("design_grid_coarse_cache"));
  const auto inputs = coarse_grid_test_inputs();
  const GridAxes fine_axes = coarse_test_fine_axes();
  std::vector<std::string> events;
  std::optional<DesignResponseGrid> shown;
  // A lambda of (step, done, total), as the panel's step reporters are, takes the step-named form.
  const auto grid = cached_design_response_grid(
      *inputs, fine_axes,
      [&](const std::string& step, std::size_t done, std::size_t total) {
        events.push_back(step + " " + std::to_string(done) + "/" + std::to_string(total));
      },
      {}, 0,
      [&](const DesignResponseGrid& coarse) {
        events.push_back("on_coarse");
        shown = coarse;
        // Shown while the fine grid is still to solve: it is in the cache already, the fine not.
        EXPECT_TRUE(coarse_test_grid_cached(*inputs, coarse_axes(fine_axes)));
        EXPECT_FALSE(coarse_test_grid_cached(*inputs, fine_axes));
      });
  EXPECT_EQ(events, (std::vector<std::string>{
                        "coarse grid 0/4", "coarse grid 1/4", "coarse grid 2/4", "coarse grid 3/4",
                        "coarse grid 4/4", "on_coarse", "fine grid 0/5", "fine grid 1/5",
                        "fine grid 2/5", "fine grid 3/5", "fine grid 4/5", "fine grid 5/5"}));
  ASSERT_TRUE(shown);
  const GridAxes expected = coarse_axes(fine_axes);
  EXPECT_EQ(shown->axes.material_a, expected.material_a);
  EXPECT_EQ(shown->axes.material_b, expected.material_b);
  EXPECT_EQ(shown->axes.fractions, expected.fractions);
  EXPECT_EQ(shown->axes.tips_m, expected.tips_m);
  ASSERT_EQ(shown->nodes.size(), 4u);
  ASSERT_EQ(grid.nodes.size(), 9u);
  expect_coarse_nodes_in_fine(*shown, grid);
  EXPECT_TRUE(coarse_test_grid_cached(*inputs, fine_axes));

  // Cached: read back as it was solved, with neither on_coarse nor progress.
  std::size_t coarse_calls = 0, progress_calls = 0;
  const auto again = cached_design_response_grid(
      *inputs, fine_axes, [&](std::size_t, std::size_t) { ++progress_calls; }, {}, 0,
      [&](const DesignResponseGrid&) { ++coarse_calls; });
  EXPECT_EQ(coarse_calls, 0u);
  EXPECT_EQ(progress_calls, 0u);
  expect_same_coarse_test_nodes(again, grid);
}

TEST(CoarseGridCache, AStopInEitherPhaseWritesNothingOfTheGridStopped) {
  const nibrig::test::ScopedCacheDir cache(nibrig::test::scratch_dir("design_grid_coarse_stop"));
  const auto inputs = coarse_grid_test_inputs();
  const GridAxes fine_axes = coarse_test_fine_axes();
  const GridAxes coarse_grid_axes = coarse_axes(fine_axes);
  constexpr unsigned kThreads = 2;  // a stop waits for at most the nodes under way: 2
  std::size_t coarse_calls = 0;
  auto count_coarse = [&](const DesignResponseGrid&) { ++coarse_calls; };

  // Stopped after the coarse grid's first node: no file at all, nothing shown.
  {
    std::stop_source stop;
    std::size_t last_done = 0;
    EXPECT_THROW(
        cached_design_response_grid(
            *inputs, fine_axes,
            numeric::StepProgress([&](const std::string& step, std::size_t done, std::size_t) {
              EXPECT_EQ(step, kCoarseGridStep);
              last_done = done;
              if (done == 1) stop.request_stop();
            }),
            stop.get_token(), kThreads, count_coarse),
        numeric::Cancelled);
    EXPECT_LE(last_done, kThreads);
    EXPECT_EQ(coarse_calls, 0u);
    EXPECT_FALSE(coarse_test_grid_cached(*inputs, coarse_grid_axes));
    EXPECT_FALSE(coarse_test_grid_cached(*inputs, fine_axes));
  }
  // Stopped after the fine grid's first node: the coarse grid was shown and stays cached, the fine
  // grid is not written.
  {
    std::stop_source stop;
    std::size_t last_fine_done = 0;
    EXPECT_THROW(
        cached_design_response_grid(
            *inputs, fine_axes,
            numeric::StepProgress([&](const std::string& step, std::size_t done, std::size_t) {
              if (step != kFineGridStep) return;
              last_fine_done = done;
              if (done == 1) stop.request_stop();
            }),
            stop.get_token(), kThreads, count_coarse),
        numeric::Cancelled);
    EXPECT_GE(last_fine_done, 1u);
    EXPECT_LE(last_fine_done, kThreads);
    EXPECT_EQ(coarse_calls, 1u);
    EXPECT_TRUE(coarse_test_grid_cached(*inputs, coarse_grid_axes));
    EXPECT_FALSE(coarse_test_grid_cached(*inputs, fine_axes));
  }
  // Run again: the coarse grid is read from the cache (nothing counted for it) and shown, and the
  // fine grid's 5 other nodes are solved, as counted through the plain Progress.
  {
    std::vector<std::size_t> done_seen, totals_seen;
    const auto grid = cached_design_response_grid(
        *inputs, fine_axes,
        [&](std::size_t done, std::size_t total) {
          done_seen.push_back(done);
          totals_seen.push_back(total);
        },
        {}, kThreads, count_coarse);
    EXPECT_EQ(coarse_calls, 2u);
    EXPECT_EQ(done_seen, (std::vector<std::size_t>{1, 2, 3, 4, 5}));
    EXPECT_EQ(totals_seen, std::vector<std::size_t>(5, 5));
    EXPECT_TRUE(coarse_test_grid_cached(*inputs, fine_axes));
  }
}

}  // namespace
}  // namespace nibrig::model::design
