#include "model/io/json_fields.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace nibrig::model::io::json_fields
