// The one exception type every reader throws on bad input: it names the file, the place in it (line,
// field, block) and what was expected, so that the CLI can print it as one clear line.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace nibrig::model::io {

class FormatError : public std::runtime_error {
 public:
  // place: "line 12, field 'Z'" or "" when the whole file is at fault.
  FormatError(const std::filesystem::path& file, const std::string& place, const std::string& problem);

  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
};

// "line N" and "line N, field 'name'": the usual places, spelled the same everywhere.
std::string line_place(std::size_t line);
std::string field_place(std::size_t line, const std::string& field);

}  // namespace nibrig::model::io
