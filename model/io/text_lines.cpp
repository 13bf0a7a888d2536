#include "model/io/text_lines.hpp"

#include <algorithm>
#include <cctype>

#include <zlib.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

#include "model/io/bounded_read.hpp"
#include "model/io/format_error.hpp"
#include "model/io/job_files.hpp"
#include "model/io/pipe_spool.hpp"
#include "model/io/quoted_csv.hpp"

namespace nibrig::model::io {

namespace {

constexpr std::size_t kTextReadChunk = 1 << 16;

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  return text;
}

std::string line_or_field(std::size_t line, std::string_view column) {
  return column.empty() ? line_place(line) : field_place(line, std::string(column));
}

}  // namespace

TextLineReader::TextLineReader(std::filesystem::path file) : file_(std::move(file)) {
  std::error_code ec;
  if (std::filesystem::is_directory(file_, ec)) {
    throw FormatError(file_, "", "is a folder, expected a file");
  }
  gz_ = gzopen(readable_path(file_).c_str(), "rb");
  if (gz_ == nullptr) {
    const int error = errno;
    throw FormatError(file_, "",
                      std::string("cannot open for reading (") +
                          (error != 0 ? std::strerror(error) : "out of memory") + ")");
  }
  note_input(file_);
  gzbuffer(gz_, kTextReadChunk);
  buffer_.resize(kTextReadChunk);
}

TextLineReader::~TextLineReader() {
  if (gz_ != nullptr) gzclose(gz_);
}

bool TextLineReader::refill() {
  // Keep the unconsumed tail of the buffer at its front, then append fresh data behind it.
  if (begin_ > 0) {
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ > kMaxTextLineBytes) {
    throw FormatError(file_, line_place(line_ + 1),
                      "a line longer than " + byte_bound_text(kMaxTextLineBytes) +
                          ": expected a text file of short lines; is this a binary file?");
  }
  if (end_ == buffer_.size()) buffer_.resize(buffer_.size() * 2);  // a long line
  const auto room = static_cast<unsigned>(buffer_.size() - end_);
  const int got = gzread(gz_, buffer_.data() + end_, room);
  int code = Z_OK;
  const char* message = gzerror(gz_, &code);
  if (got < 0 || (code != Z_OK && code != Z_STREAM_END)) {
    // zlib hands out what it decompressed before a truncated stream ended (Z_BUF_ERROR "unexpected
    // end of file"); the lines in it are complete and valid, the one being assembled is not.
    std::string problem = "compressed data is truncated or corrupt (zlib: ";
    problem += (code == Z_ERRNO) ? std::strerror(errno) : (message != nullptr ? message : "?");
    problem += ")";
    if (got <= 0) {
      throw FormatError(file_, line_place(line_ + 1), problem);
    }
    pending_error_ = problem;
  }
  if (got <= 0) {
    at_end_ = true;
    return false;
  }
  end_ += static_cast<std::size_t>(got);
  bytes_read_ += static_cast<std::size_t>(got);
  if (bytes_read_ > kMaxTextBytes) {
    throw FormatError(file_, line_place(line_ + 1),
                      "more than " + byte_bound_text(kMaxTextBytes) +
                          " of text: no recording, table or judgment file is near that size; is "
                          "this the right file?");
  }
  return true;
}

bool TextLineReader::next(std::string& line) {
  std::size_t scan_from = begin_;
  for (;;) {
    const void* found = std::memchr(buffer_.data() + scan_from, '\n', end_ - scan_from);
    if (found != nullptr) {
      const auto newline =
          static_cast<std::size_t>(static_cast<const char*>(found) - buffer_.data());
      line.assign(buffer_.data() + begin_, newline - begin_);
      begin_ = newline + 1;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      ++line_;
      terminated_ = true;
      check_utf8(line);
      return true;
    }
    if (!pending_error_.empty()) {
      throw FormatError(file_, line_place(line_ + 1), pending_error_);
    }
    const std::size_t scanned = end_ - begin_;
    if (at_end_ || !refill()) {
      if (end_ == begin_) return false;
      line.assign(buffer_.data() + begin_, end_ - begin_);
      begin_ = end_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      ++line_;
      terminated_ = false;
      check_utf8(line);
      return true;
    }
    scan_from = begin_ + scanned;
  }
}

void TextLineReader::check_utf8(const std::string& line) const {
  const auto bad = invalid_utf8_at(line);
  if (!bad) return;
  throw FormatError(file_, line_place(line_),
                    "byte " + std::to_string(*bad + 1) + " is not UTF-8 text (" +
                        in_quotes(std::string_view(line).substr(*bad, 8)) +
                        "); is this a binary file?");
}

std::optional<std::size_t> invalid_utf8_at(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xBF;  // the allowed range of the second byte
    if (c < 0x80) {
      ++i;
      continue;
    } else if (c >= 0xC2 && c <= 0xDF) {
      length = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      length = 3;
      if (c == 0xE0) low = 0xA0;   // no overlong forms
      if (c == 0xED) high = 0x9F;  // no surrogates
    } else if (c >= 0xF0 && c <= 0xF4) {
      length = 4;
      if (c == 0xF0) low = 0x90;
      if (c == 0xF4) high = 0x8F;  // nothing past U+10FFFF
    } else {
      return i;
    }
    if (i + length > text.size()) return i;
    for (std::size_t k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      const unsigned char lo = k == 1 ? low : 0x80, hi = k == 1 ? high : 0xBF;
      if (next < lo || next > hi) return i;
    }
    i += length;
  }
  return std::nullopt;
}

std::vector<std::string_view> split_fields(std::string_view line, char sep) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t pos = line.find(sep, start);
    if (pos == std::string_view::npos) {
      fields.push_back(line.substr(start));
      return fields;
    }
    fields.push_back(line.substr(start, pos - start));
    start = pos + 1;
  }
}

std::string in_quotes(std::string_view text) {
  constexpr std::size_t kMaxShown = 40;
  const bool utf8 = !invalid_utf8_at(text);
  std::size_t shown = std::min(text.size(), kMaxShown);
  if (utf8) {  // back to the start of a sequence, so that the cut leaves valid UTF-8
    while (shown < text.size() && shown > 0 &&
           (static_cast<unsigned char>(text[shown]) & 0xC0) == 0x80)
      --shown;
  }
  std::string out = "'";
  for (std::size_t i = 0; i < shown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f || (!utf8 && c >= 0x80)) {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 0xf];
    } else {
      out += static_cast<char>(c);
    }
  }
  if (text.size() > shown) out += "...";
  out += "'";
  return out;
}

double parse_number(std::string_view field, const std::filesystem::path& file, std::size_t line,
                    std::string_view column) {
  const std::string_view text = trim(field);
  if (text.empty()) {
    throw FormatError(file, line_or_field(line, column), "expected a number, found an empty field");
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range) {
    throw FormatError(file, line_or_field(line, column),
                      "expected a number within double range, found " + in_quotes(text));
  }
  if (error != std::errc() || end == text.data()) {
    throw FormatError(file, line_or_field(line, column),
                      "expected a number, found " + in_quotes(text));
  }
  if (end != text.data() + text.size()) {
    throw FormatError(
        file, line_or_field(line, column),
        "expected a number, found " + in_quotes(text) + " (trailing characters after " +
            in_quotes(std::string_view(text.data(), static_cast<std::size_t>(end - text.data()))) +
            ")");
  }
  if (!std::isfinite(value)) {
    throw FormatError(file, line_or_field(line, column),
                      "expected a finite number, found " + in_quotes(text));
  }
  return value;
}

std::optional<double> parse_optional_number(std::string_view field,
                                            const std::filesystem::path& file, std::size_t line,
                                            std::string_view column) {
  if (field.empty()) return std::nullopt;
  return parse_number(field, file, line, column);
}

long long parse_integer(std::string_view field, const std::filesystem::path& file, std::size_t line,
                        std::string_view column) {
  const std::string_view text = trim(field);
  if (text.empty()) {
    throw FormatError(file, line_or_field(line, column),
                      "expected a whole number, found an empty field");
  }
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range) {
    throw FormatError(file, line_or_field(line, column),
                      "expected a whole number within 64-bit range, found " + in_quotes(text));
  }
  if (error != std::errc() || end != text.data() + text.size()) {
    throw FormatError(file, line_or_field(line, column),
                      "expected a whole number, found " + in_quotes(text));
  }
  return value;
}

CsvHeader::CsvHeader(std::string_view line, std::filesystem::path file, std::size_t line_number,
                     std::string expected, char sep)
    : file_(std::move(file)),
      line_number_(line_number),
      expected_(std::move(expected)),
      found_(line) {
  // A byte-order mark written by spreadsheet programs is not part of the first column's name.
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (line.substr(0, kBom.size()) == kBom) line.remove_prefix(kBom.size());
  if (line.find('"') == std::string_view::npos) {
    for (std::string_view name : split_fields(line, sep)) names_.emplace_back(trim(name));
  } else {
    for (const std::string& name : split_quoted_fields(line, file_, line_number, sep))
      names_.emplace_back(trim(name));
  }
}

std::optional<std::size_t> CsvHeader::find(std::string_view name) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return i;
  }
  return std::nullopt;
}

std::size_t CsvHeader::column(std::string_view name) const {
  if (auto index = find(name)) return *index;
  throw FormatError(file_, line_place(line_number_),
                    "missing column '" + std::string(name) + "' (expected header " + expected_ +
                        ", found " + in_quotes(found_) + ")");
}

namespace {
CsvHeader read_header_line(TextLineReader& lines, const std::string& expected, char sep) {
  std::string line;
  if (!lines.next(line)) {
    throw FormatError(lines.file(), "", "empty file: expected a header line " + expected);
  }
  return CsvHeader(line, lines.file(), lines.line_number(), expected, sep);
}
}  // namespace

CsvReader::CsvReader(std::filesystem::path file, std::string expected_header, char sep)
    : lines_(std::move(file)),
      sep_(sep),
      expected_header_(std::move(expected_header)),
      header_(read_header_line(lines_, expected_header_, sep_)) {}

bool CsvReader::next(std::vector<std::string_view>& fields) {
  std::size_t first_blank = 0;
  while (lines_.next(row_)) {
    if (trim(row_).empty()) {
      if (first_blank == 0) first_blank = lines_.line_number();
      continue;
    }
    if (first_blank != 0) {
      throw FormatError(
          lines_.file(), line_place(first_blank),
          "blank line inside the data (expected a row like " + expected_header_ + ")");
    }
    if (row_.find('"') == std::string::npos) {
      fields = split_fields(row_, sep_);
    } else {
      unquoted_ = split_quoted_fields(row_, lines_.file(), lines_.line_number(), sep_);
      fields.assign(unquoted_.begin(), unquoted_.end());
    }
    // More fields than the header names is a wrong or damaged file, refused like fewer: a reader
    // finds its columns by name and would silently take the wrong ones.
    if (fields.size() > header_.names().size()) {
      throw FormatError(lines_.file(), line_place(lines_.line_number()),
                        "expected " + std::to_string(header_.names().size()) + " fields (" +
                            expected_header_ + "), found " + std::to_string(fields.size()) +
                            ": more fields than the header names");
    }
    return true;
  }
  return false;
}

bool CsvReader::cut_off_last_row(const std::vector<std::string_view>& fields, std::size_t needed,
                                 std::vector<std::string>& warnings) const {
  if (fields.size() >= needed || !row_unterminated()) return false;
  warnings.push_back("line " + std::to_string(lines_.line_number()) + " is cut off (" +
                     std::to_string(fields.size()) + " of " + std::to_string(needed) +
                     " fields, no line ending) and was dropped");
  return true;
}

void CsvReader::require_fields(const std::vector<std::string_view>& fields,
                               std::size_t needed) const {
  if (fields.size() >= needed) return;
  throw FormatError(lines_.file(), line_place(lines_.line_number()),
                    "expected " + std::to_string(needed) + " fields (" + expected_header_ +
                        "), found " + std::to_string(fields.size()));
}

std::optional<std::string> csv_stem(const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  for (std::string_view ending : {std::string_view(".csv.gz"), std::string_view(".csv")}) {
    if (name.size() > ending.size() && name.compare(name.size() - ending.size(), ending.size(),
                                                    ending.data(), ending.size()) == 0) {
      return name.substr(0, name.size() - ending.size());
    }
  }
  return std::nullopt;
}

long long parse_unix_ms(std::string_view field, const std::filesystem::path& file, std::size_t line,
                        std::string_view column) {
  const long long ms = parse_integer(field, file, line, column);
  if (ms < 0) {
    throw FormatError(file, field_place(line, std::string(column)),
                      "expected Unix time in milliseconds (>= 0), found " + in_quotes(field));
  }
  return ms;
}

std::optional<double> positive_number_in_name(std::string_view text) {
  if (text.empty() || std::isdigit(static_cast<unsigned char>(text.front())) == 0) {
    return std::nullopt;
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
      value <= 0.0) {
    return std::nullopt;
  }
  return value;
}

}  // namespace nibrig::model::io
