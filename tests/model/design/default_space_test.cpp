// The panel's default space: computed on a cache miss and written under its key, read back on a
// hit without computing, keyed by every input, computed again over a corrupt file, and leaving
// nothing behind when cancelled. The space is the demo's (its -log likelihood, seed 2018).
#include "model/design/default_space.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stop_token>

#include "model/io/bundled_assets.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

// The bootstrap does not touch the fit, so a few refits test the caching as well as the demo's
// 200 would, at a fraction of the time under the sanitizers.
DefaultsOptions quick(const std::filesystem::path& cache) {
  DefaultsOptions o;
  o.cache_dir = cache;
  o.bootstrap_resamples = 8;
  return o;
}

using nibrig::test::files_in;

TEST(DefaultSpace, AMissComputesAndWritesAndAHitReadsWithoutComputing) {
  const auto cache = nibrig::test::scratch_dir("default_space_hit") / "cache";
  // Through the environment, as the panel finds it.
  ::setenv("NIBRIG_CACHE", cache.c_str(), 1);
  DefaultsOptions o = quick({});
  std::size_t calls = 0;
  o.progress = [&](const std::string&, std::size_t, std::size_t) { ++calls; };

  const Cached<DefaultSpace> first = default_space(o);
  EXPECT_TRUE(first.computed);
  EXPECT_GT(calls, 0u);
  EXPECT_TRUE(first.warnings.empty());
  EXPECT_EQ(first.file, cache / ("default_space-" + default_space_key(o).hex() + ".json"));
  EXPECT_EQ(files_in(cache), std::vector<std::filesystem::path>{first.file});  // no temporary
  // The demo's space (`nibrig demo` printed -log likelihood 967.6 before the study moved out of
  // the command line): 0.1 covers the print's rounding and a build whose floating-point
  // contraction differs, far below what another seed or catalog weighting changes (986.5 with the
  // catalog's stored descriptors).
  EXPECT_NEAR(first.value.space.negative_log_likelihood, 967.6, 0.1);
  EXPECT_EQ(first.value.space.responses, 1966u);

  calls = 0;
  const Cached<DefaultSpace> second = default_space(o);
  EXPECT_FALSE(second.computed);
  EXPECT_EQ(calls, 0u);
  // JSON keeps 17 significant digits, so the round trip is exact to the last bits; 1e-12 only
  // allows for the text conversion's last ulp.
  EXPECT_TRUE(second.value.space.coordinates.isApprox(first.value.space.coordinates, 1e-12));
  ASSERT_EQ(second.value.space.regions.size(), 15u);
  EXPECT_TRUE(second.value.space.regions[3].covariance.isApprox(
      first.value.space.regions[3].covariance, 1e-12));
  // Everything the panel draws comes back too.
  const auto tools = default_space_tools(second.value);
  EXPECT_EQ(tools.tools.size(), default_space_tools(first.value).tools.size());
  EXPECT_GT(tools.tools.size(), 15u);
  ::unsetenv("NIBRIG_CACHE");
}

TEST(DefaultSpace, EveryInputIsInTheKeyButNotHowItIsComputed) {
  const auto dir = nibrig::test::scratch_dir("default_space_key");
  const DefaultsOptions base = quick(dir);
  const std::string key = default_space_key(base).hex();
  EXPECT_EQ(DefaultsOptions{}.bootstrap_resamples, 200);  // the demo's, unless a test asks

  DefaultsOptions threads = base;
  threads.threads = 1;
  EXPECT_EQ(default_space_key(threads).hex(), key);  // results do not depend on threads

  DefaultsOptions refits = base;
  refits.bootstrap_resamples = 9;
  EXPECT_NE(default_space_key(refits).hex(), key);

  // A copy keys as the bundled file (content, not path); one changed byte does not.
  const auto bundled = nibrig::test::assets_dir() / "default_catalog.json";
  std::ifstream in(bundled, std::ios::binary);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  DefaultsOptions copy = base;
  copy.catalog = dir / "catalog.json";
  std::ofstream(copy.catalog, std::ios::binary) << content;
  EXPECT_EQ(default_space_key(copy).hex(), key);
  std::ofstream(copy.catalog, std::ios::binary) << content << ' ';
  EXPECT_NE(default_space_key(copy).hex(), key);

  DefaultsOptions threshold = base;
  threshold.threshold_curve = dir / "threshold.csv";
  std::filesystem::copy_file(io::default_threshold_curve(), threshold.threshold_curve);
  EXPECT_EQ(default_space_key(threshold).hex(), key);
  std::ofstream(threshold.threshold_curve, std::ios::app) << "\n";
  EXPECT_NE(default_space_key(threshold).hex(), key);

  DefaultsOptions missing = base;
  missing.catalog = dir / "nowhere.json";
  try {
    default_space_key(missing);
    FAIL() << "a missing catalog was keyed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nowhere.json"), std::string::npos) << e.what();
  }
}

TEST(DefaultSpace, ACorruptCacheFileIsComputedAgainWithAWarning) {
  const auto cache = nibrig::test::scratch_dir("default_space_corrupt");
  const DefaultsOptions o = quick(cache);
  const auto file = cache / ("default_space-" + default_space_key(o).hex() + ".json");
  std::ofstream(file) << R"({"format": "nibrig-space", "version": 1, "stimuli": [)";  // cut short

  const Cached<DefaultSpace> space = default_space(o);
  EXPECT_TRUE(space.computed);
  ASSERT_EQ(space.warnings.size(), 1u);
  EXPECT_NE(space.warnings[0].find(file.string()), std::string::npos) << space.warnings[0];
  // The computed space replaced the corrupt file.
  EXPECT_FALSE(default_space(o).computed);
}

TEST(DefaultSpace, ASpaceThatCannotBeKeptIsStillReturned) {
  const auto dir = nibrig::test::scratch_dir("default_space_unwritable");
  std::ofstream(dir / "a_file") << "not a folder";
  const Cached<DefaultSpace> space = default_space(quick(dir / "a_file" / "cache"));
  EXPECT_TRUE(space.computed);
  EXPECT_EQ(space.value.space.stimuli.size(), 15u);
  ASSERT_EQ(space.warnings.size(), 1u);
  EXPECT_NE(space.warnings[0].find("cannot be kept"), std::string::npos) << space.warnings[0];
}

TEST(DefaultSpace, ACancelledComputationLeavesNoFile) {
  const auto cache = nibrig::test::scratch_dir("default_space_cancel") / "cache";
  std::stop_source cancel;
  DefaultsOptions o = quick(cache);
  o.bootstrap_resamples = 200;  // so that the cancel lands mid-bootstrap
  o.stop = cancel.get_token();
  o.progress = [&](const std::string& step, std::size_t done, std::size_t) {
    if (step == "bootstrap refits" && done == 2) cancel.request_stop();
  };
  EXPECT_THROW(default_space(o), numeric::Cancelled);
  EXPECT_TRUE(files_in(cache).empty());
  // Nor does a cancel after the space was kept take it away: the next call reads it.
  o.stop = {};
  o.progress = {};
  o.bootstrap_resamples = 8;
  ASSERT_TRUE(default_space(o).computed);
  o.stop = cancel.get_token();
  EXPECT_FALSE(default_space(o).computed);
}

}  // namespace
}  // namespace nibrig::model::design
