#include "model/io/user_cache.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

namespace nibrig::model::io {
namespace {

TEST(UserCache, FollowsNibrigCacheThenXdgThenHome) {
  ::setenv("NIBRIG_CACHE", "/tmp/nibrig-cache-test", 1);
  EXPECT_EQ(user_cache_dir(), "/tmp/nibrig-cache-test");
  ::unsetenv("NIBRIG_CACHE");
  ::setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  EXPECT_EQ(user_cache_dir(), "/tmp/xdg/nibrig");
  ::unsetenv("XDG_CACHE_HOME");
  ::setenv("HOME", "/tmp/home", 1);
  EXPECT_EQ(user_cache_dir(), "/tmp/home/.cache/nibrig");
}

// The FNV-1a reference: the empty input is the offset basis; one part is hashed as its 8-byte
// length then its bytes, so the split between parts counts.
TEST(CacheKey, IsFnv1aOverLengthsAndBytesSoTheSplitBetweenPartsCounts) {
  EXPECT_EQ(CacheKey().hex(), "cbf29ce484222325");
  EXPECT_NE(CacheKey().add("ab").add("c").hex(), CacheKey().add("a").add("bc").hex());
  EXPECT_EQ(CacheKey().add("ab").add(2.0).hex(), CacheKey().add("ab").add(2.0).hex());
  EXPECT_NE(CacheKey().add(2.0).hex(), CacheKey().add(std::nextafter(2.0, 3.0)).hex());
  EXPECT_EQ(CacheKey().add(std::int64_t{7}).hex().size(), 16u);
}

TEST(CacheKey, KeysAFileByItsContentAndNamesAMissingOne) {
  const auto file = std::filesystem::temp_directory_path() / "nibrig_cache_key_test.txt";
  { std::ofstream(file) << "modes"; }
  EXPECT_EQ(CacheKey().add_file(file).hex(), CacheKey().add("modes").hex());
  std::filesystem::remove(file);
  try {
    CacheKey().add_file(file);
    FAIL() << "a missing file was keyed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nibrig_cache_key_test.txt"), std::string::npos);
  }
}

}  // namespace
}  // namespace nibrig::model::io
