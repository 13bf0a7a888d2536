#include "model/io/text_lines.hpp"

#include <gtest/gtest.h>

#include <random>

#include "model/io/format_error.hpp"
#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

// Lines of random digits: gzip cannot shrink them much, so cutting the compressed file at half its
// size cuts the text near its middle rather than at the very end.
std::vector<std::string> noisy_lines(std::size_t count) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> digit(0, 9);
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < count; ++i) {
    std::string line = std::to_string(i) + ",";
    for (int k = 0; k < 40; ++k) line += static_cast<char>('0' + digit(random));
    lines.push_back(line);
  }
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& line : lines) text += line + "\n";
  return text;
}

TEST(TextLineReader, ReadsPlainAndGzipFilesAlike) {
  const auto dir = nibrig::test::scratch_dir("text_lines_alike");
  const std::string content = "a,b\r\n1,2\n\nlast";
  nibrig::test::write_text(dir / "plain.csv", content);
  nibrig::test::write_gzip(dir / "packed.csv.gz", content);
  for (const auto& file : {dir / "plain.csv", dir / "packed.csv.gz"}) {
    TextLineReader reader(file);
    std::string line;
    std::vector<std::string> lines;
    while (reader.next(line)) {
      lines.push_back(line);
      EXPECT_EQ(reader.line_number(), lines.size());
    }
    // CRLF is stripped like LF; the blank line is kept; the last line has no ending.
    EXPECT_EQ(lines, (std::vector<std::string>{"a,b", "1,2", "", "last"})) << file;
    EXPECT_FALSE(reader.last_line_terminated());
  }
}

TEST(TextLineReader, ReadsLinesLongerThanItsBuffer) {
  const auto dir = nibrig::test::scratch_dir("text_lines_long");
  const std::string long_line(300'000, 'x');
  nibrig::test::write_gzip(dir / "long.csv.gz", "short\n" + long_line + "\nend\n");
  TextLineReader reader(dir / "long.csv.gz");
  std::string line;
  ASSERT_TRUE(reader.next(line));
  ASSERT_TRUE(reader.next(line));
  EXPECT_EQ(line, long_line);
  ASSERT_TRUE(reader.next(line));
  EXPECT_EQ(line, "end");
  EXPECT_TRUE(reader.last_line_terminated());
  EXPECT_FALSE(reader.next(line));
}

TEST(TextLineReader, TruncatedGzipDeliversTheIntactLinesThenNamesTheBrokenOne) {
  const auto dir = nibrig::test::scratch_dir("text_lines_truncated");
  const auto lines = noisy_lines(20'000);
  const auto file = dir / "cut.csv.gz";
  nibrig::test::write_truncated_gzip(file, join_lines(lines), 0.5);

  TextLineReader reader(file);
  std::string line;
  std::size_t good = 0;
  const std::string message = format_error_of([&] {
    while (reader.next(line)) {
      ASSERT_EQ(line, lines[good]) << "line " << good + 1 << " was delivered damaged";
      ++good;
    }
  });
  // About half of the text survives the cut; every delivered line is intact, and the error names
  // the first line that is not.
  EXPECT_GT(good, lines.size() / 4);
  EXPECT_LT(good, lines.size());
  expect_message_names(message, {"cut.csv.gz", "line " + std::to_string(good + 1), "truncated"});
}

TEST(TextLineReader, CorruptGzipIsAnErrorNotAShortFile) {
  const auto dir = nibrig::test::scratch_dir("text_lines_corrupt");
  const auto file = dir / "corrupt.csv.gz";
  nibrig::test::write_gzip(file, join_lines(noisy_lines(5'000)));
  {
    std::fstream bytes(file, std::ios::in | std::ios::out | std::ios::binary);
    bytes.seekp(static_cast<std::streamoff>(std::filesystem::file_size(file) / 2));
    const char garbage[64] = {'\x55', '\x13', '\x7f', '\x00', '\xff'};
    bytes.write(garbage, sizeof garbage);
  }
  const std::string message = format_error_of([&] {
    TextLineReader reader(file);
    std::string line;
    while (reader.next(line)) {
    }
  });
  expect_message_names(message, {"corrupt.csv.gz", "line ", "truncated or corrupt"});
}

TEST(TextLineReader, MissingFileAndFolderAreNamed) {
  const auto dir = nibrig::test::scratch_dir("text_lines_missing");
  expect_message_names(format_error_of([&] { TextLineReader reader(dir / "nope.csv"); }),
                       {"nope.csv", "cannot open"});
  expect_message_names(format_error_of([&] { TextLineReader reader(dir); }), {"is a folder"});
}

TEST(SplitFields, KeepsEmptyFields) {
  EXPECT_EQ(split_fields(",,a,"), (std::vector<std::string_view>{"", "", "a", ""}));
  EXPECT_EQ(split_fields(""), (std::vector<std::string_view>{""}));
  EXPECT_EQ(split_fields("1;2", ';'), (std::vector<std::string_view>{"1", "2"}));
}

TEST(ParseNumber, AcceptsDecimalNotation) {
  const std::filesystem::path file = "f.csv";
  EXPECT_EQ(parse_number("-896", file, 3, "X"), -896.0);
  EXPECT_EQ(parse_number(" 2001.864909 ", file, 3, "Z"), 2001.864909);
  EXPECT_EQ(parse_number("1e-3", file, 3, "Z"), 1e-3);
}

TEST(ParseNumber, RejectsWithFileLineFieldAndExpectation) {
  const std::filesystem::path file = "forces.csv";
  struct Case {
    std::string_view field;
    std::string_view says;
  };
  for (const Case& c :
       {Case{"", "empty field"}, Case{"abc", "expected a number, found 'abc'"},
        Case{"12abc", "trailing characters"}, Case{"nan", "finite"}, Case{"-inf", "finite"},
        Case{"infinity", "finite"}, Case{"1e999", "double range"}}) {
    const std::string message = format_error_of([&] { parse_number(c.field, file, 12, "Z"); });
    expect_message_names(message, {"forces.csv", "line 12, field 'Z'", c.says});
  }
}

TEST(ParseInteger, RejectsFractionsAndText) {
  const std::filesystem::path file = "t.csv";
  EXPECT_EQ(parse_integer("1515589189348", file, 2, "timestamp"), 1515589189348LL);
  expect_message_names(format_error_of([&] { parse_integer("3.5", file, 4, "count_a"); }),
                       {"t.csv", "line 4, field 'count_a'", "expected a whole number"});
  expect_message_names(
      format_error_of([&] { parse_integer("99999999999999999999", file, 4, "n"); }),
      {"64-bit range"});
}

TEST(CsvHeader, FindsColumnsByNameAndNamesTheMissingOne) {
  const CsvHeader header("\xEF\xBB\xBFTimeStamp, X ,Y", "f.csv", 1, "TimeStamp,X,Y,Z");
  EXPECT_EQ(header.column("TimeStamp"), 0u);  // the byte-order mark is not part of the name
  EXPECT_EQ(header.column("X"), 1u);
  EXPECT_FALSE(header.find("Z").has_value());
  expect_message_names(
      format_error_of([&] { header.column("Z"); }),
      {"f.csv", "line 1", "missing column 'Z'", "expected header TimeStamp,X,Y,Z"});
}

TEST(CsvReader, BlankLinesOnlyAtTheEnd) {
  const auto dir = nibrig::test::scratch_dir("csv_reader_blank");
  nibrig::test::write_text(dir / "ok.csv", "a,b\n1,2\n\n\n");
  CsvReader ok(dir / "ok.csv", "a,b");
  std::vector<std::string_view> fields;
  ASSERT_TRUE(ok.next(fields));
  EXPECT_FALSE(ok.next(fields));

  nibrig::test::write_text(dir / "gap.csv", "a,b\n1,2\n\n3,4\n");
  CsvReader gap(dir / "gap.csv", "a,b");
  ASSERT_TRUE(gap.next(fields));
  expect_message_names(format_error_of([&] { gap.next(fields); }),
                       {"gap.csv", "line 3", "blank line inside the data"});

  nibrig::test::write_text(dir / "empty.csv", "");
  expect_message_names(format_error_of([&] { CsvReader empty(dir / "empty.csv", "a,b"); }),
                       {"empty.csv", "empty file", "a,b"});
}

TEST(CsvStem, StripsOnlyCsvEndings) {
  EXPECT_EQ(csv_stem("x/p2h_note_2.2N_14_1.csv.gz"), "p2h_note_2.2N_14_1");
  EXPECT_EQ(csv_stem("a.csv"), "a");
  EXPECT_FALSE(csv_stem("a.txt").has_value());
  EXPECT_FALSE(csv_stem(".csv").has_value());
}

// Readers stop at a size no real text file reaches: /dev/zero has no line ending at all, and an
// unbounded line would grow memory until the machine runs out.
TEST(TextLineReader, AnEndlessInputIsRefusedAtTheLineBound) {
  TextLineReader reader("/dev/zero");
  std::string line;
  const std::string message = format_error_of([&] { reader.next(line); });
  expect_message_names(message, {"/dev/zero", "line 1", "longer than 1 MiB"});
}

TEST(TextLineReader, ALineThatIsNotUtf8IsRefusedWithItsBytesEscaped) {
  const auto dir = nibrig::test::scratch_dir("text_lines_utf8");
  // Latin-1 'é' (0xE9) alone, an overlong '/' (C0 AF) and a UTF-16 surrogate (ED A0 80): none is
  // UTF-8. A real multi-byte name ("Müller", "γ") is.
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"caf\xE9", "byte 4"}, {"a\xC0\xAF", "byte 2"}, {"x\xED\xA0\x80", "byte 2"}};
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const auto file = dir / ("bad" + std::to_string(i) + ".csv");
    nibrig::test::write_text(file, "name\nM\xC3\xBCller,\xCE\xB3\n" + bad[i].first + "\n");
    TextLineReader reader(file);
    std::string line;
    ASSERT_TRUE(reader.next(line));
    ASSERT_TRUE(reader.next(line));
    const std::string message = format_error_of([&] { reader.next(line); });
    expect_message_names(message, {file.string(), "line 3", bad[i].second, "not UTF-8", "\\x"});
  }
}

TEST(InQuotes, EscapesBytesThatAreNotUtf8AndCutsLongTextBetweenCharacters) {
  EXPECT_EQ(in_quotes("ab\x01\xFF"), "'ab\\x01\\xff'");
  EXPECT_EQ(in_quotes("M\xC3\xBCller"), "'M\xC3\xBCller'");
  // 39 ASCII bytes then a 2-byte character: the cut at 40 falls inside it, so it moves before it.
  const std::string shown = in_quotes(std::string(39, 'a') + "\xC3\xBC" + "tail");
  EXPECT_EQ(shown, "'" + std::string(39, 'a') + "...'");
  EXPECT_FALSE(invalid_utf8_at(shown).has_value());
}

TEST(CsvReader, ARowWithMoreFieldsThanTheHeaderIsRefused) {
  const auto dir = nibrig::test::scratch_dir("csv_extra_fields");
  nibrig::test::write_text(dir / "extra.csv", "a,b\n1,2\n3,4,5\n");
  CsvReader reader(dir / "extra.csv", "'a,b'");
  std::vector<std::string_view> fields;
  ASSERT_TRUE(reader.next(fields));
  const std::string message = format_error_of([&] { reader.next(fields); });
  expect_message_names(message, {"extra.csv", "line 3", "expected 2 fields", "found 3"});
}

}  // namespace
}  // namespace nibrig::model::io
