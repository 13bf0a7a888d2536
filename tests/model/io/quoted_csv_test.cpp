// Quoted CSV fields: what csv_field quotes splits back into the same text, and a table of another
// shape is refused naming the file and the line.
#include "model/io/quoted_csv.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

TEST(QuotedCsv, FieldsSplitBackIntoTheTextQuoted) {
  const std::vector<std::string> texts{"plain", "a,b", "say \"hi\"", "", "pred:DM85:0.5,vero:0.5/glass"};
  std::string line;
  for (const auto& t : texts) line += (line.empty() ? "" : ",") + csv_field(t);
  EXPECT_EQ(csv_field("plain"), "plain");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_quoted("plain"), "\"plain\"");
  EXPECT_EQ(split_quoted_fields(line, "x.csv", 1), texts);
}

TEST(QuotedCsv, ReadsATableAndRefusesWhatIsNotOne) {
  const auto dir = nibrig::test::scratch_dir("quoted_csv");
  {
    std::ofstream(dir / "good.csv") << "name,value\n\"a,b\",1\nc,2\n\n";
  }
  const QuotedCsv good = read_quoted_csv(dir / "good.csv");
  EXPECT_EQ(good.header, (std::vector<std::string>{"name", "value"}));
  ASSERT_EQ(good.rows.size(), 2u);
  EXPECT_EQ(good.rows[0][0], "a,b");
  EXPECT_EQ(good.line_numbers[1], 3u);

  const auto refused = [&](const std::string& name, const std::string& text,
                           const std::string& expected) {
    {
      std::ofstream(dir / name) << text;
    }
    try {
      read_quoted_csv(dir / name);
      ADD_FAILURE() << name << " was read";
    } catch (const FormatError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(name), std::string::npos) << m;
      EXPECT_NE(m.find(expected), std::string::npos) << m;
    }
  };
  refused("open_quote.csv", "name,value\n\"a,b,1\n", "line 2");
  refused("short_row.csv", "name,value\nc\n", "expected 2 fields");
  refused("blank_inside.csv", "name,value\nc,1\n\nd,2\n", "blank line");
  refused("empty.csv", "", "empty file");
}

}  // namespace
}  // namespace nibrig::model::io
