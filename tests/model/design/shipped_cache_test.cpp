// The shipped layer beneath the user cache (io::shipped_twin, read by cached_default): a default
// the build computed is read from there when the user cache lacks it, never written to, never
// preferred to the user's own file, and only ever for a file of the user cache itself.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "model/design/cached_default.hpp"
#include "model/io/user_cache.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

using nibrig::test::files_in;

struct Layers {
  std::filesystem::path root, user, shipped;
  nibrig::test::ScopedCacheDir cache;
  nibrig::test::ScopedEnvironment layer;

  explicit Layers(const std::string& name)
      : root(nibrig::test::scratch_dir(name)),
        user(root / "user"),
        shipped(root / "shipped"),
        cache(user),
        layer("NIBRIG_SHIPPED_CACHE", shipped.string()) {
    std::filesystem::create_directories(shipped);
  }
};

std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void put(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// A default whose value is its file's text: "bad" does not read.
Cached<std::string> cached_text(const std::filesystem::path& file, int& computed) {
  return cached_default<std::string>(
      file, "test default",
      [](const std::filesystem::path& f) {
        const std::string text = text_of(f);
        if (text == "bad") throw std::runtime_error("bad file");
        return text;
      },
      [&] {
        ++computed;
        return std::string("computed");
      },
      [](const std::filesystem::path& f, const std::string& text) { put(f, text); });
}

TEST(ShippedCache, AFileTheUserCacheLacksIsReadFromTheShippedLayerAndNotCopied) {
  Layers l("shipped_cache_read");
  put(l.shipped / "thing-0123.json", "shipped");
  int computed = 0;
  const auto got = cached_text(l.user / "thing-0123.json", computed);
  EXPECT_EQ(got.value, "shipped");
  EXPECT_FALSE(got.computed);
  EXPECT_EQ(computed, 0);
  EXPECT_EQ(got.file, l.shipped / "thing-0123.json");
  EXPECT_TRUE(files_in(l.user).empty());
}

TEST(ShippedCache, TheUsersOwnFileComesFirst) {
  Layers l("shipped_cache_user_first");
  put(l.shipped / "thing-0123.json", "shipped");
  put(l.user / "thing-0123.json", "user");
  int computed = 0;
  const auto got = cached_text(l.user / "thing-0123.json", computed);
  EXPECT_EQ(got.value, "user");
  EXPECT_EQ(got.file, l.user / "thing-0123.json");
}

TEST(ShippedCache, AShippedFileThatDoesNotReadIsComputedIntoTheUserCacheAndLeftAsItWas) {
  Layers l("shipped_cache_bad");
  put(l.shipped / "thing-0123.json", "bad");
  int computed = 0;
  const auto got = cached_text(l.user / "thing-0123.json", computed);
  EXPECT_TRUE(got.computed);
  EXPECT_EQ(computed, 1);
  EXPECT_EQ(text_of(l.user / "thing-0123.json"), "computed");
  EXPECT_EQ(text_of(l.shipped / "thing-0123.json"), "bad");
  ASSERT_EQ(got.warnings.size(), 1u);
  EXPECT_NE(got.warnings[0].find((l.shipped / "thing-0123.json").string()), std::string::npos)
      << got.warnings[0];
}

TEST(ShippedCache, OnlyAFileOfTheUserCacheHasATwinAndAnEmptyLayerIsNone) {
  Layers l("shipped_cache_scope");
  put(l.shipped / "thing-0123.json", "shipped");
  // A cache folder a caller chose (as the tests' own) is its own: nothing read from the layer.
  int computed = 0;
  EXPECT_TRUE(cached_text(l.root / "elsewhere" / "thing-0123.json", computed).computed);
  EXPECT_EQ(io::shipped_twin(l.root / "elsewhere" / "thing-0123.json"), std::filesystem::path());
  EXPECT_EQ(io::shipped_twin(l.user / "thing-0123.json"), l.shipped / "thing-0123.json");
  EXPECT_EQ(io::shipped_twin(l.user / "other-0123.json"), std::filesystem::path());
  const nibrig::test::ScopedEnvironment none("NIBRIG_SHIPPED_CACHE", "");
  EXPECT_EQ(io::shipped_cache_dir(), std::filesystem::path());
  EXPECT_EQ(io::shipped_twin(l.user / "thing-0123.json"), std::filesystem::path());
}

}  // namespace
}  // namespace nibrig::model::design
