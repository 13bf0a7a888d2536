#include "model/io/quoted_csv.hpp"

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::io {

std::string csv_quoted(std::string_view text) {
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  return csv_quoted(text);
}

std::vector<std::string> split_quoted_fields(std::string_view line,
                                             const std::filesystem::path& file,
                                             std::size_t line_number, char sep) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  bool closed = false;  // the field's closing quote was read: only a separator may follow
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') {
        fields.back() += c;
      } else if (i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else {
        quoted = false;
        closed = true;
      }
    } else if (c == sep) {
      fields.emplace_back();
      closed = false;
    } else if (closed) {
      throw FormatError(file, line_place(line_number),
                        "text after a quoted field's closing quote (field " +
                            std::to_string(fields.size()) + "): expected '" + std::string(1, sep) +
                            "' or the line's end");
    } else if (c == '"' && fields.back().find_first_not_of(" \t") == std::string::npos) {
      fields.back().clear();  // spaces before an opening quote are not part of the field
      quoted = true;
    } else {
      fields.back() += c;
    }
  }
  if (quoted)
    throw FormatError(file, line_place(line_number),
                      "a quoted field is not closed (expected a '\"' before the line ends)");
  return fields;
}

QuotedCsv read_quoted_csv(const std::filesystem::path& file) {
  TextLineReader lines(file);
  QuotedCsv table;
  std::string line;
  if (!lines.next(line)) throw FormatError(file, "", "empty file: expected a header line");
  table.header = split_quoted_fields(line, file, lines.line_number());
  std::size_t blank = 0;  // the line number of a blank line not yet followed by a row
  while (lines.next(line)) {
    if (line.empty()) {
      if (blank == 0) blank = lines.line_number();
      continue;
    }
    if (blank != 0) throw FormatError(file, line_place(blank), "blank line among the rows");
    auto fields = split_quoted_fields(line, file, lines.line_number());
    if (fields.size() != table.header.size())
      throw FormatError(file, line_place(lines.line_number()),
                        "expected " + std::to_string(table.header.size()) +
                            " fields as in the header, found " + std::to_string(fields.size()));
    table.rows.push_back(std::move(fields));
    table.line_numbers.push_back(lines.line_number());
  }
  return table;
}

}  // namespace nibrig::model::io
