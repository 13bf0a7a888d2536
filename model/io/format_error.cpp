#include "model/io/format_error.hpp"

namespace nibrig::model::io {

namespace {
std::string compose(const std::filesystem::path& file, const std::string& place,
                    const std::string& problem) {
  std::string message = file.string();
  if (!place.empty()) message += " " + place;
  message += ": " + problem;
  return message;
}
}  // namespace

FormatError::FormatError(const std::filesystem::path& file, const std::string& place,
                         const std::string& problem)
    : std::runtime_error(compose(file, place, problem)), file_(file) {}

std::string line_place(std::size_t line) { return "line " + std::to_string(line); }

std::string field_place(std::size_t line, const std::string& field) {
  return "line " + std::to_string(line) + ", field '" + field + "'";
}

}  // namespace nibrig::model::io
