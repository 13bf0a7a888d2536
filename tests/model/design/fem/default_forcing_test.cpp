// The default forcing model: computed on a cache miss (designs simulated, then the fit) and written
// under its key, read back on a hit without computing (also by load_prediction_inputs without a
// forcing file), keyed by every input file and the resolution, and leaving nothing behind when
// cancelled. The model is the demo's (54 exemplars, 1.98 dB).
// The corrupt-file path is the one default_space_test.cpp checks (cached_default.hpp): a second
// forcing computation would double this suite's time under the sanitizers.
#include "model/design/default_forcing.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <stop_token>

#include "model/design/prediction_inputs.hpp"
#include "model/io/bundled_assets.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

using nibrig::test::files_in;

TEST(DefaultForcing, AMissComputesAndWritesAndAHitReadsWithoutComputing) {
  DefaultsOptions o;
  o.cache_dir = nibrig::test::scratch_dir("default_forcing_hit") / "cache";
  std::map<std::string, std::size_t> last_done, totals;
  o.progress = [&](const std::string& step, std::size_t done, std::size_t total) {
    last_done[step] = done;
    totals[step] = total;
  };

  const Cached<forcing::ForcingModel> first = default_forcing_model(o);
  EXPECT_TRUE(first.computed);
  EXPECT_TRUE(first.warnings.empty());
  EXPECT_EQ(files_in(o.cache_dir), std::vector<std::filesystem::path>{first.file});
  ASSERT_EQ(last_done.size(), 2u);
  EXPECT_GT(totals.at("designs simulated"), 1u);
  EXPECT_EQ(last_done.at("designs simulated"), totals.at("designs simulated"));
  EXPECT_EQ(last_done.at("forcing fit"), 1u);
  // The demo's model: `nibrig demo` reported 54 exemplars on 6 surfaces, residual RMS 1.98 dB
  // (two decimals, so 0.01 is its rounding).
  EXPECT_EQ(first.value.exemplar_count(), 54u);
  EXPECT_EQ(first.value.surface_forcing.size(), 6u);
  EXPECT_NEAR(first.value.residual_rms_db, 1.98, 0.01);
  EXPECT_FALSE(first.value.held_out_descriptor_errors.empty());

  last_done.clear();
  const Cached<forcing::ForcingModel> second = default_forcing_model(o);
  EXPECT_FALSE(second.computed);
  EXPECT_TRUE(last_done.empty());
  // The file keeps 17 significant digits: equal to the last ulp of the text conversion.
  EXPECT_NEAR(second.value.residual_rms_db, first.value.residual_rms_db, 1e-12);
  const auto& a = first.value.surface_forcing.at("office");
  const auto& b = second.value.surface_forcing.at("office");
  ASSERT_EQ(a.size(), b.size());
  EXPECT_NEAR(b[3][5], a[3][5], 1e-12 * a[3][5]);

  // Predicting without a forcing file at the same resolution takes this model from the cache: no
  // second file, no design simulated, the same numbers.
  const nibrig::test::ScopedCacheDir cache(o.cache_dir);
  forcing::ForcingInputOptions at_default;
  at_default.modes = kDefaultForcingModes;
  at_default.mesh_size = kDefaultForcingMeshSize;
  std::size_t designs = 0;
  const auto inputs = load_prediction_inputs(at_default, "", std::nullopt,
                                             [&](const forcing::DesignResponse&, std::size_t,
                                                 std::size_t) { ++designs; });
  EXPECT_EQ(designs, 0u);
  EXPECT_EQ(files_in(o.cache_dir), std::vector<std::filesystem::path>{first.file});
  EXPECT_NEAR(inputs->model.residual_rms_db, first.value.residual_rms_db, 1e-12);
}

TEST(DefaultForcing, EveryInputFileIsInTheKey) {
  const auto dir = nibrig::test::scratch_dir("default_forcing_key");
  const std::string key = default_forcing_key().hex();
  // Copies key as the bundled files (content, not path); one appended byte does not.
  const std::vector<std::pair<std::filesystem::path DefaultsOptions::*, std::filesystem::path>>
      inputs{{&DefaultsOptions::catalog, io::default_catalog()},
             {&DefaultsOptions::materials, io::default_materials()},
             {&DefaultsOptions::stylus_design, io::default_stylus_design()}};
  for (const auto& [member, bundled] : inputs) {
    DefaultsOptions o;
    o.*member = dir / bundled.filename();
    std::filesystem::copy_file(bundled, o.*member);
    EXPECT_EQ(default_forcing_key(o).hex(), key) << bundled;
    std::ofstream(o.*member, std::ios::app) << ' ';
    EXPECT_NE(default_forcing_key(o).hex(), key) << bundled;
  }
  // The designs' resolution is an input too; the default one is the key above.
  EXPECT_EQ(default_forcing_key({}, {kDefaultForcingModes, kDefaultForcingMeshSize}).hex(), key);
  EXPECT_NE(default_forcing_key({}, {16, kDefaultForcingMeshSize}).hex(), key);
  EXPECT_NE(default_forcing_key({}, {kDefaultForcingModes, 0.003}).hex(), key);
  // How the space is computed is not the forcing model's business.
  DefaultsOptions refits;
  refits.bootstrap_resamples = 8;
  EXPECT_EQ(default_forcing_key(refits).hex(), key);
}

TEST(DefaultForcing, ACancelledComputationLeavesNoFile) {
  DefaultsOptions o;
  o.cache_dir = nibrig::test::scratch_dir("default_forcing_cancel") / "cache";
  std::stop_source cancel;
  o.stop = cancel.get_token();
  std::size_t designs = 0;
  o.progress = [&](const std::string& step, std::size_t done, std::size_t) {
    if (step != "designs simulated" || done == 0) return;
    designs = done;
    cancel.request_stop();  // after the first design: the next one is never meshed
  };
  EXPECT_THROW(default_forcing_model(o), numeric::Cancelled);
  EXPECT_EQ(designs, 1u);
  EXPECT_TRUE(files_in(o.cache_dir).empty());
}

}  // namespace
}  // namespace nibrig::model::design
