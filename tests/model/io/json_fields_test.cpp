#include "model/io/json_fields.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <fstream>
#include <string>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io::json_fields {
namespace {

// Every JSON reader parses through parse_file: a key named twice in one object is refused with the
// path to it, wherever the object sits; the same key in two objects is not a duplicate.
TEST(JsonParseFile, AKeyNamedTwiceInOneObjectIsRefusedWithItsPath) {
  struct Case {
    const char* json;
    const char* refused_at;  // nullptr: accepted
  };
  const Case cases[] = {
      {R"({"tool": "vero2", "tool": "cryon"})", "field 'tool'"},
      {R"({"calibration": {"lever": 14, "gain": 2, "lever": 15}})", "field 'calibration.lever'"},
      {R"({"pairings": [{"tool": "a"}, {"tool": "b", "tool": "c"}]})", "field 'pairings[1].tool'"},
      {R"({"m": [[1, 2], [3, {"k": 1, "k": 2}]]})", "field 'm[1][1].k'"},
      {R"({"a": {"k": 1}, "b": {"k": 1}, "k": [{"k": 1}, {"k": 2}]})", nullptr},
  };
  const auto folder = test::scratch_dir("json_duplicate_keys");
  for (const Case& c : cases) {
    SCOPED_TRACE(c.json);
    const auto file = folder / "f.json";
    std::ofstream(file) << c.json;
    if (c.refused_at == nullptr) {
      EXPECT_NO_THROW(parse_file(file));
      continue;
    }
    try {
      parse_file(file);
      ADD_FAILURE() << "accepted";
    } catch (const FormatError& e) {
      EXPECT_NE(std::string(e.what()).find(c.refused_at), std::string::npos) << e.what();
      EXPECT_EQ(e.file(), file);
    }
  }
}

// /dev/zero never ends: the reader stops at its bound and names the file, instead of growing.
TEST(JsonParseFile, AnEndlessInputStopsAtTheBoundNamingTheFile) {
  try {
    parse_file("/dev/zero");
    FAIL() << "/dev/zero was parsed";
  } catch (const FormatError& e) {
    EXPECT_EQ(e.file(), "/dev/zero");
    EXPECT_NE(std::string(e.what()).find("256 MiB"), std::string::npos) << e.what();
  }
}

long peak_kib() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// A space file 200 KB larger, nested 100,000 deep, took `space predict` to 4.5 GB (every open level
// kept the path to itself). Refused at kMaxJsonDepth, where it is, and in bounded memory.
TEST(JsonParseFile, DeepNestingIsRefusedWhereItPassesTheBound) {
  const auto dir = nibrig::test::scratch_dir("json_deep");
  const std::size_t levels = 100000;
  {
    std::ofstream out(dir / "space.json");
    out << "{\"dimensions\": ";
    for (std::size_t i = 0; i < levels; ++i) out << "[";
    for (std::size_t i = 0; i < levels; ++i) out << "]";
    out << "}";
  }
  const long before = peak_kib();
  try {
    parse_file(dir / "space.json");
    FAIL() << "100,000 levels were parsed";
  } catch (const FormatError& e) {
    EXPECT_EQ(e.file(), dir / "space.json");
    const std::string message = e.what();
    EXPECT_NE(message.find(std::to_string(kMaxJsonDepth)), std::string::npos) << message;
    // The path to the first level too deep: 62 arrays inside the object's member.
    EXPECT_NE(message.find("dimensions[0]"), std::string::npos) << message;
  }
  // 10,000 levels took 268 MB before; the refusal holds the text (200 KB) and 64 levels. 64 MiB
  // leaves room for the allocator's and the sanitizer's own growth.
  EXPECT_LT(peak_kib() - before, 64 * 1024);

  // Every JSON file nibrig ships nests well inside the bound.
  for (const auto& entry : std::filesystem::recursive_directory_iterator(nibrig::test::assets_dir()))
    if (entry.path().extension() == ".json") EXPECT_NO_THROW(parse_file(entry.path())) << entry.path();
}

}  // namespace
}  // namespace nibrig::model::io::json_fields
