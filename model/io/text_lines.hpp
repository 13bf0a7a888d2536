// Line-by-line reading of the text files every importer shares: plain or gzip-compressed files
// through zlib, strict number parsing and header-column lookup. Every failure is a FormatError
// naming the file, the line (and field) and what was expected.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

struct gzFile_s;  // zlib's handle type, kept out of this header

namespace nibrig::model::io {

// Reads a file one line at a time; gzip-compressed and plain files alike (zlib reads plain files
// through unchanged). A truncated or corrupt compressed stream throws a FormatError naming the line
// at which the data broke off, instead of looking like a short but valid file. A line longer than
// kMaxTextLineBytes or more than kMaxTextBytes in all (after decompression) is refused, so that
// /dev/zero or a binary file is an error and not a process that fills memory. So is a line that is
// not UTF-8: names read from it end up in JSON, which holds UTF-8 only, and in messages.
inline constexpr std::size_t kMaxTextLineBytes = std::size_t{1} << 20;
inline constexpr std::size_t kMaxTextBytes = std::size_t{1} << 30;

class TextLineReader {
 public:
  explicit TextLineReader(std::filesystem::path file);
  ~TextLineReader();
  TextLineReader(const TextLineReader&) = delete;
  TextLineReader& operator=(const TextLineReader&) = delete;

  // The next line without its ending ("\n" or "\r\n"); false at the end of the file.
  bool next(std::string& line);

  // 1-based number of the line last returned by next(); 0 before the first.
  std::size_t line_number() const { return line_; }

  // False when the line last returned had no line ending: it was the file's last and the writer may
  // have been stopped in the middle of it.
  bool last_line_terminated() const { return terminated_; }

  const std::filesystem::path& file() const { return file_; }

 private:
  bool refill();
  void check_utf8(const std::string& line) const;

  std::filesystem::path file_;
  gzFile_s* gz_ = nullptr;
  std::vector<char> buffer_;
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
  bool at_end_ = false;
  std::string
      pending_error_;  // zlib reported truncation: thrown once the buffered lines are used up
  std::size_t line_ = 0;
  std::size_t bytes_read_ = 0;
  bool terminated_ = true;
};

// The offset of the first byte of `text` that does not belong to a well-formed UTF-8 sequence;
// nullopt when the whole text is UTF-8 (ASCII included).
std::optional<std::size_t> invalid_utf8_at(std::string_view text);

// Splits a line at every separator; no quoting (for names and stamps; CsvReader and CsvHeader take
// fields quoted as RFC 4180 and spreadsheets write them).
std::vector<std::string_view> split_fields(std::string_view line, char sep = ',');

// A field as it may appear in an error message: quoted, control bytes and bytes that are not UTF-8
// escaped as \xNN, long text shortened (never inside a UTF-8 sequence).
std::string in_quotes(std::string_view text);

// A finite decimal number (surrounding spaces allowed). Rejects empty fields, text, trailing
// characters, NaN and infinities: FormatError "file line N, field 'column': expected a number,
// ...".
double parse_number(std::string_view field, const std::filesystem::path& file, std::size_t line,
                    std::string_view column);

// The same, where an empty field means no number (a table's cell with nothing to report).
std::optional<double> parse_optional_number(std::string_view field,
                                            const std::filesystem::path& file, std::size_t line,
                                            std::string_view column);

// A whole number written without a fraction or exponent (counts, millisecond timestamps).
long long parse_integer(std::string_view field, const std::filesystem::path& file, std::size_t line,
                        std::string_view column);

// A Unix timestamp in milliseconds (a whole number >= 0), as the paper's accelerometer and drawing
// files write it; errors like parse_integer, naming `column`.
long long parse_unix_ms(std::string_view field, const std::filesystem::path& file, std::size_t line,
                        std::string_view column);

// A plain positive decimal number written in a file NAME ("2.2", "13.3", "4"): digits first, no sign,
// finite and > 0; nullopt otherwise, so the caller can say which part of the name was wrong.
std::optional<double> positive_number_in_name(std::string_view text);

// The header line of a CSV file: finds columns by name so that column order does not matter, and
// names the expected header when a column is missing.
class CsvHeader {
 public:
  // expected: the header as the format documents it, quoted in errors ("TimeStamp,X,Y,Z").
  CsvHeader(std::string_view line, std::filesystem::path file, std::size_t line_number,
            std::string expected, char sep = ',');

  std::optional<std::size_t> find(std::string_view name) const;
  // Throws "missing column 'Z' (expected header ..., found ...)".
  std::size_t column(std::string_view name) const;

  const std::vector<std::string>& names() const { return names_; }
  std::size_t line_number() const { return line_number_; }

 private:
  std::filesystem::path file_;
  std::size_t line_number_;
  std::string expected_;
  std::string found_;
  std::vector<std::string> names_;
};

// The data rows of a CSV file after its header line. A field may be quoted ("cryon/office", with
// '""' for a quote inside), as spreadsheets write text. Blank lines at the very end are tolerated
// (editors add them); a blank line with data after it is an error, never skipped silently.
class CsvReader {
 public:
  // Throws "empty file: expected a header line '<expected_header>'" for a file without any line.
  CsvReader(std::filesystem::path file, std::string expected_header, char sep = ',');

  const CsvHeader& header() const { return header_; }

  // The next data row split into fields (views into an internal buffer, valid until the next call).
  // A row with more fields than the header line is a FormatError naming the line.
  bool next(std::vector<std::string_view>& fields);

  std::size_t line_number() const { return lines_.line_number(); }
  // True when the row last returned is the file's last and has no line ending.
  bool row_unterminated() const { return !lines_.last_line_terminated(); }

  // True when the row last returned is the file's unterminated last one with fewer than `needed`
  // fields: its writer was stopped in the middle of it. Then adds the warning "line N is cut off (K
  // of M fields, no line ending) and was dropped" and the caller stops reading; false otherwise.
  bool cut_off_last_row(const std::vector<std::string_view>& fields, std::size_t needed,
                        std::vector<std::string>& warnings) const;

  // Throws unless the row has at least `needed` fields: "line N: expected M fields (...), found K".
  void require_fields(const std::vector<std::string_view>& fields, std::size_t needed) const;

  const std::filesystem::path& file() const { return lines_.file(); }

 private:
  TextLineReader lines_;
  char sep_;
  std::string expected_header_;
  std::string row_;
  std::vector<std::string> unquoted_;  // a row's fields when it quoted some
  CsvHeader header_;
};

// The name of a CSV file without its ".csv" or ".csv.gz" ending; nullopt for any other name.
std::optional<std::string> csv_stem(const std::filesystem::path& file);

}  // namespace nibrig::model::io
