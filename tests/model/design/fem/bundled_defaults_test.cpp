// The bundled defaults the build computed (<build>/defaults, NIBRIG_SHIPPED_DEFAULTS): a first
// start with an empty user cache computes none of them, and what was shipped is what the code
// computes.
#include "model/design/bundled_defaults.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "model/design/default_forcing.hpp"
#include "model/design/design_grid_file.hpp"
#include "model/design/prediction_inputs.hpp"
#include "model/io/user_cache.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

std::string bytes_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(BundledDefaults, AFirstStartComputesNoneOfThemAndWritesNothing) {
  const auto shipped = io::shipped_cache_dir();
  ASSERT_FALSE(shipped.empty()) << "a Release tree computes the bundled defaults as it builds";
  const auto user = nibrig::test::scratch_dir("bundled_defaults_first_start") / "cache";
  const nibrig::test::ScopedCacheDir cache(user);
  const auto made = compute_bundled_defaults();
  ASSERT_EQ(made.size(), 5u);
  for (const auto& d : made) {
    EXPECT_FALSE(d.computed) << d.what;
    EXPECT_EQ(d.file.parent_path(), shipped) << d.what;
  }
  EXPECT_TRUE(nibrig::test::files_in(user).empty());

  // The grid the panel's Design view asks for by default (ui/panel/design_view.hpp: vero-DM85 over
  // 1-4 mm, the template's resolution, the default forcing model) is the one shipped.
  const auto model = default_forcing_model();
  const auto inputs = load_prediction_inputs({}, model.file, model.value);
  EXPECT_TRUE(load_cached_design_grid(*inputs, even_axes("vero", "DM85", kDefaultFractionPoints,
                                                         0.001, 0.004, kDefaultTipPoints))
                  .has_value());
  EXPECT_TRUE(nibrig::test::files_in(user).empty());
}

// The forcing model the panel opens on, computed here into a cache of the test's own, is the
// shipped file byte for byte: the build's computation is this code's, with nothing of its own.
TEST(BundledDefaults, TheShippedForcingModelIsWhatTheCodeComputes) {
  DefaultsOptions o;
  o.cache_dir = nibrig::test::scratch_dir("bundled_defaults_recomputed") / "cache";
  const auto fresh = default_forcing_model(o);
  ASSERT_TRUE(fresh.computed);
  const auto shipped = io::shipped_cache_dir() / fresh.file.filename();
  ASSERT_TRUE(std::filesystem::is_regular_file(shipped)) << shipped;
  EXPECT_EQ(bytes_of(fresh.file), bytes_of(shipped));
}

}  // namespace
}  // namespace nibrig::model::design
