// What nibrig writes holds no NaN, no infinity and no text that is not UTF-8: the writer refuses,
// naming the file and the field, and an earlier file of that name is kept: nibrig never writes a
// file its own reader refuses.
#include "model/io/finite_output.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "model/io/atomic_file.hpp"
#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

std::string refusal_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const UnwritableOutput& e) {
    return e.what();
  }
  ADD_FAILURE() << "written, though it holds what no reader takes";
  return "";
}

TEST(JsonText, ANonFiniteNumberAnywhereIsRefusedByItsPath) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const struct {
    nlohmann::json value;
    std::string path;
  } cases[] = {
      {{{"mu", nan}}, "field 'mu'"},
      {{{"modes", {{{"f", 1.0}}, {{"f", -inf}}}}}, "field 'modes[1].f'"},
      {{{"a", {{"b", {1.0, 2.0, inf}}}}}, "field 'a.b[2]'"},
      {nlohmann::json(nan), "the value"},
  };
  for (const auto& c : cases) {
    const std::string message = refusal_of([&] { json_text(c.value, "out.json"); });
    nibrig::test::expect_message_names(message, {"out.json", c.path, "not a finite number"});
  }
  // Finite numbers of any size, and integers, are written as they are.
  EXPECT_EQ(json_text({{"x", 1e300}, {"n", 3}}, "out.json", -1), "{\"n\":3,\"x\":1e+300}\n");
}

TEST(JsonText, TextThatIsNotUtf8IsRefusedNotThrownAsALibraryError) {
  const std::string message =
      refusal_of([&] { json_text({{"stimuli", {"ok", "caf\xE9"}}}, "study.json"); });
  nibrig::test::expect_message_names(message, {"study.json", "field 'stimuli[1]'", "not UTF-8",
                                               "'caf\\xe9'"});
}

TEST(CsvFinite, NanAndInfinityInAnySpellingAreRefusedByLineAndField) {
  for (const std::string field : {"nan", "-nan", "NaN", "inf", "-inf", "+Infinity", " nan", "\"nan\""}) {
    const std::string message =
        refusal_of([&] { check_csv_finite("tool,mu\ncryon,0.3\nvero," + field + "\n", "t.csv"); });
    nibrig::test::expect_message_names(message, {"t.csv", "line 3", "field 2"});
  }
  // Words that merely contain the letters, and empty fields, are data.
  EXPECT_NO_THROW(check_csv_finite("tool,note\nnano,infinite\ninfo,\n", "t.csv"));
}

TEST(CsvFinite, AWriteOfACsvWithNanKeepsTheEarlierFile) {
  const auto dir = nibrig::test::scratch_dir("finite_output_csv");
  nibrig::test::write_text(dir / "table.csv", "a\n1\n");
  refusal_of([&] { write_file_atomically(dir / "table.csv", "a\nnan\n"); });
  std::ifstream in(dir / "table.csv");
  const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, "a\n1\n");
  // Only tables are read this way: a text file may say "inf" in prose.
  EXPECT_NO_THROW(write_file_atomically(dir / "notes.txt", "nan\n"));
}

}  // namespace
}  // namespace nibrig::model::io
