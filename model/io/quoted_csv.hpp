// CSV tables whose text fields may be quoted: names a user chose (a stimulus "a,b/c"), reasons in
// words. A quoted field is enclosed in '"' with any '"' inside doubled, as spreadsheets write it.
// CsvReader (text_lines.hpp) reads quoted fields through split_quoted_fields too.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace nibrig::model::io {

// `text` as one field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(std::string_view text);
// `text` quoted whatever it holds.
std::string csv_quoted(std::string_view text);

// A line's fields, quotes removed. Throws FormatError naming `file` and the line for a quote that
// is not closed before the line ends (a quoted field holds no line break here), or text between a
// closing quote and the next separator.
std::vector<std::string> split_quoted_fields(std::string_view line,
                                             const std::filesystem::path& file,
                                             std::size_t line_number, char sep = ',');

// The header and the rows, each row as many fields as the header. Blank lines at the very end are
// tolerated (editors add them); a blank line with rows after it is an error. Throws FormatError
// naming the file and line: an empty file, a row of another length, an unclosed quote; and what
// TextLineReader throws.
struct QuotedCsv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::size_t> line_numbers;  // of each row, 1-based
};
QuotedCsv read_quoted_csv(const std::filesystem::path& file);

}  // namespace nibrig::model::io
