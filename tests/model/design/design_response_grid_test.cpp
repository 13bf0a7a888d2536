// The design-response grid without the FEM: interpolation checked on a grid whose node values are
// bilinear in (λ, tip) by construction (so interpolation must reproduce them to rounding), the
// refusals, the cache file read back bit for bit, a corrupt cache recomputed rather than trusted,
// the cache key moved by every input, and a stop before the first node computing nothing.
#include "model/design/design_response_grid.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "model/design/design_grid_file.hpp"
#include "model/io/format_error.hpp"
#include "model/numeric/cancellation.hpp"
#include "tests/model/design/hand_made_forcing_model.hpp"
#include "tests/model/design/synthetic_design_grid.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

using ::testing::HasSubstr;

using grid_testing::bilinear;
using grid_testing::hand_made_inputs;
using grid_testing::synthetic_grid;

TEST(DesignResponseGrid, InterpolationIsExactForResponsesBilinearInMixAndTip) {
  const DesignResponseGrid grid = synthetic_grid();
  for (const auto& [fraction, tip] : std::vector<std::pair<double, double>>{
           {0.25, 0.0015}, {0.9, 0.0031}, {0.5, 0.002}, {0.0, 0.004}, {1.0, 0.001}, {0.1, 0.0039}}) {
    const SimulatedResponse r = interpolate_response(grid, fraction, tip);
    for (std::size_t j = 0; j < grid.frequencies_hz.size(); ++j)  // rounding of exp/log only
      EXPECT_NEAR(std::log(r.response_magnitude[j]),
                  bilinear(0.1 * j, -0.3, 0.2, 0.05 * j, fraction, tip), 1e-12)
          << fraction << " " << tip << " at " << grid.frequencies_hz[j] << " Hz";
    for (int k = 0; k < grid.modes; ++k) {
      EXPECT_NEAR(std::log(r.modal.omega[k]), bilinear(5.0 + k, -0.1, 0.02, 0.01, fraction, tip),
                  1e-12);
      EXPECT_NEAR(r.modal.zeta[k], bilinear(0.01, 0.02, 0.001, 0.0, fraction, tip), 1e-15);
      const double gain = k == 1 ? bilinear(-0.5, 1.5, 0.0, 0.0, fraction, tip)
                                 : bilinear(1.0 + k, 0.5, 0.1, 0.0, fraction, tip);
      EXPECT_NEAR(r.modal.input[k] * r.modal.output[k], gain, 1e-12) << "mode " << k;
    }
  }
  // At a node it is the node: its design's name too.
  const SimulatedResponse at_node = interpolate_response(grid, 0.5, 0.002);
  EXPECT_EQ(at_node.design_name, grid.node(1, 1).design_name);
  // Mode 1's gain is −0.5 at λ = 0 and 0.25 at λ = 0.5: a sign change along each of the 3 tip
  // columns; from 0.25 to 1 at λ = 1 it grows fourfold, under the tenfold that counts.
  EXPECT_EQ(count_mode_jumps(grid), 3u);
}

TEST(DesignResponseGrid, RefusesPointsOutsideTheGridSayingByHowFar) {
  const DesignResponseGrid grid = synthetic_grid();
  try {
    interpolate_response(grid, 0.5, 0.0045);
    FAIL() << "a 4.5 mm tip is beyond the grid's 4 mm";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("0.5 mm above its range 1 mm to 4 mm"));
  }
  EXPECT_THROW(interpolate_response(grid, -0.1, 0.002), std::invalid_argument);
  EXPECT_THROW(interpolate_response(grid, 1.2, 0.002), std::invalid_argument);
  // A slider's end computed with rounding is its end, not a refusal.
  EXPECT_NO_THROW(interpolate_response(grid, 1.0 + 1e-15, 0.004 * (1 + 1e-15)));
  // Axes: too few nodes, out of order, one material twice.
  EXPECT_THROW(even_axes("vero", "DM85", 1, 0.001, 0.004, 3), std::invalid_argument);
  EXPECT_THROW(validate(GridAxes{"vero", "DM85", {0, 0.6, 0.5}, {0.001, 0.002}}),
               std::invalid_argument);
  EXPECT_THROW(validate(GridAxes{"vero", "vero", {0, 1}, {0.001, 0.002}}), std::invalid_argument);
  const GridAxes even = even_axes("vero", "DM85", 5, 0.001, 0.004, 7);
  EXPECT_EQ(even.fractions, (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
  EXPECT_DOUBLE_EQ(even.tips_m[1], 0.0015);
  EXPECT_EQ(even.tips_m.back(), 0.004);
}

TEST(DesignResponseGrid, TheEndsOfTheMixAreSingleMaterials) {
  const GridAxes axes{"vero", "DM85", {0, 1}, {0.001, 0.004}};
  EXPECT_EQ(to_string(grid_point(axes, 0.0, 0.002)), to_string(parse_design_point("vero,tip=2mm")));
  EXPECT_EQ(to_string(grid_point(axes, 1.0, 0.002)), to_string(parse_design_point("DM85,tip=2mm")));
  EXPECT_DOUBLE_EQ(grid_point(axes, 0.25, 0.002).fraction_of("DM85"), 0.25);
}

TEST(DesignGridFile, ReadsBackWhatItWroteBitForBit) {
  const auto dir = nibrig::test::scratch_dir("design_grid_file");
  const DesignResponseGrid grid = synthetic_grid();
  write_design_grid(dir / "grid.json", grid, "0123456789abcdef");
  const DesignResponseGrid back = read_design_grid(dir / "grid.json", "0123456789abcdef");
  EXPECT_EQ(back.axes.fractions, grid.axes.fractions);
  EXPECT_EQ(back.axes.tips_m, grid.axes.tips_m);
  EXPECT_EQ(back.frequencies_hz, grid.frequencies_hz);
  ASSERT_EQ(back.nodes.size(), grid.nodes.size());
  for (std::size_t n = 0; n < grid.nodes.size(); ++n) {
    EXPECT_EQ(back.nodes[n].design_name, grid.nodes[n].design_name);
    EXPECT_EQ(back.nodes[n].response_magnitude, grid.nodes[n].response_magnitude);
    EXPECT_EQ(back.nodes[n].modal.omega, grid.nodes[n].modal.omega);
    EXPECT_EQ(back.nodes[n].modal.output, grid.nodes[n].modal.output);
  }
  EXPECT_EQ(back.mode_jumps, 3u);
  // Another key: another set of inputs, refused naming the field.
  try {
    read_design_grid(dir / "grid.json", "fedcba9876543210");
    FAIL() << "a grid of other inputs was read";
  } catch (const io::FormatError& e) {
    EXPECT_THAT(e.what(), HasSubstr("grid.json"));
    EXPECT_THAT(e.what(), HasSubstr("key"));
  }
}

TEST(DesignGridFile, ATruncatedOrInconsistentFileIsRefusedNamingTheFile) {
  const auto dir = nibrig::test::scratch_dir("design_grid_corrupt");
  write_design_grid(dir / "grid.json", synthetic_grid(), "k");
  std::string text;
  {
    std::ifstream in(dir / "grid.json");
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  {
    std::ofstream out(dir / "truncated.json");
    out << text.substr(0, text.size() / 2);
  }
  EXPECT_THROW(read_design_grid(dir / "truncated.json"), io::FormatError);
  DesignResponseGrid short_node = synthetic_grid();
  short_node.nodes[4].response_magnitude.pop_back();
  write_design_grid(dir / "short.json", short_node, "k");
  try {
    read_design_grid(dir / "short.json");
    FAIL() << "a node with |H| at too few frequencies was read";
  } catch (const io::FormatError& e) {
    EXPECT_THAT(e.what(), HasSubstr("short.json"));
    EXPECT_THAT(e.what(), HasSubstr("node 4"));
  }
}

TEST(DesignGridCache, EveryInputTheGridDependsOnMovesTheKey) {
  auto inputs = hand_made_inputs();
  const GridAxes axes = even_axes("vero", "DM85", 3, 0.001, 0.004, 3);
  const std::string key = design_grid_cache_key(*inputs, axes);
  EXPECT_EQ(key, design_grid_cache_key(*inputs, axes));  // the same inputs: the same grid
  GridAxes other = axes;
  other.material_b = "DM95";
  EXPECT_NE(design_grid_cache_key(*inputs, other), key);
  other = axes;
  other.tips_m[1] += 1e-9;
  EXPECT_NE(design_grid_cache_key(*inputs, other), key);
  other = even_axes("vero", "DM85", 4, 0.001, 0.004, 3);
  EXPECT_NE(design_grid_cache_key(*inputs, other), key);
  inputs->setup.modes = 9;
  EXPECT_NE(design_grid_cache_key(*inputs, axes), key);
  inputs->setup.modes = 8;
  inputs->setup.mesh_size = 0.003;
  EXPECT_NE(design_grid_cache_key(*inputs, axes), key);
  inputs->setup.mesh_size = 0.004;
  inputs->model.frequencies_hz.back() += 1;
  EXPECT_NE(design_grid_cache_key(*inputs, axes), key);
  inputs->model.frequencies_hz.back() -= 1;
  // The template file's content, not its name: a copy elsewhere is the same grid, an edit is not.
  const auto dir = nibrig::test::scratch_dir("design_grid_key");
  std::filesystem::copy_file(inputs->design_template_file, dir / "template.json");
  inputs->design_template_file = dir / "template.json";
  EXPECT_EQ(design_grid_cache_key(*inputs, axes), key);
  std::ofstream(dir / "template.json", std::ios::app) << "\n";
  EXPECT_NE(design_grid_cache_key(*inputs, axes), key);
  std::filesystem::copy_file(inputs->materials_file, dir / "materials.json");
  inputs->design_template_file = nibrig::test::assets_dir() / "designs" / "stylus_vero_tip2mm.json";
  inputs->materials_file = dir / "materials.json";
  EXPECT_EQ(design_grid_cache_key(*inputs, axes), key);
  std::ofstream(dir / "materials.json", std::ios::app) << " ";
  EXPECT_NE(design_grid_cache_key(*inputs, axes), key);
}

TEST(DesignGridCache, ACorruptCacheIsRemovedAndRecomputedNotTrusted) {
  const auto dir = nibrig::test::scratch_dir("design_grid_cache");
  ::setenv("NIBRIG_CACHE", dir.c_str(), 1);
  const auto inputs = hand_made_inputs();
  DesignResponseGrid grid = synthetic_grid();
  const std::string key = design_grid_cache_key(*inputs, grid.axes);
  EXPECT_FALSE(load_cached_design_grid(*inputs, grid.axes));  // nothing cached yet
  write_design_grid(design_grid_cache_file(key), grid, key);
  const auto cached = load_cached_design_grid(*inputs, grid.axes);
  ASSERT_TRUE(cached);
  EXPECT_EQ(cached->nodes[3].response_magnitude, grid.nodes[3].response_magnitude);
  std::ofstream(design_grid_cache_file(key)) << "{\"format\": \"nibrig-design-grid\", \"vers";
  EXPECT_FALSE(load_cached_design_grid(*inputs, grid.axes));
  EXPECT_FALSE(std::filesystem::exists(design_grid_cache_file(key)));
  ::unsetenv("NIBRIG_CACHE");
}

TEST(DesignResponseGrid, AStopBeforeTheFirstNodeComputesNothing) {
  const auto inputs = hand_made_inputs();
  std::stop_source stop;
  stop.request_stop();
  std::size_t calls = 0;
  EXPECT_THROW(compute_design_response_grid(
                   inputs->setup, even_axes("vero", "DM85", 2, 0.001, 0.004, 2),
                   [&](std::size_t, std::size_t) { ++calls; }, stop.get_token()),
               numeric::Cancelled);
  EXPECT_EQ(calls, 0u);
  // A tip range beyond the model's fitted tips is refused before any FEM.
  EXPECT_THROW(compute_design_response_grid(inputs->setup,
                                            even_axes("vero", "DM85", 2, 0.001, 0.005, 2)),
               std::invalid_argument);
}

}  // namespace
}  // namespace nibrig::model::design
