#include "model/io/finite_output.hpp"

#include <cctype>
#include <cmath>
#include <optional>

#include "model/io/json_fields.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::io {
namespace {

struct Unwritable {
  std::string path;
  std::string problem;
};

std::optional<Unwritable> first_unwritable(const nlohmann::json& value, const std::string& path) {
  if (value.is_number_float()) {
    if (!std::isfinite(value.get<double>()))
      return Unwritable{path, "is not a finite number (the computation behind it failed)"};
  } else if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    if (invalid_utf8_at(text)) return Unwritable{path, "is not UTF-8 text: " + in_quotes(text)};
  } else if (value.is_object()) {
    for (const auto& [key, member] : value.items()) {
      if (invalid_utf8_at(key))
        return Unwritable{path, "has a member name that is not UTF-8 text: " + in_quotes(key)};
      if (auto found = first_unwritable(member, json_fields::member_path(path, key))) return found;
    }
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      if (auto found = first_unwritable(value[i], json_fields::element_path(path, i))) return found;
  }
  return std::nullopt;
}

bool names_non_finite(std::string_view field) {
  while (!field.empty() && (field.front() == ' ' || field.front() == '"')) field.remove_prefix(1);
  while (!field.empty() && (field.back() == ' ' || field.back() == '"' || field.back() == '\r'))
    field.remove_suffix(1);
  if (!field.empty() && (field.front() == '-' || field.front() == '+')) field.remove_prefix(1);
  std::string lower;
  for (char c : field) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "nan" || lower == "inf" || lower == "infinity" || lower.rfind("nan(", 0) == 0;
}

}  // namespace

std::string json_text(const nlohmann::json& json, const std::filesystem::path& file, int indent) {
  if (const auto found = first_unwritable(json, "")) {
    const std::string where = found->path.empty() ? "the value" : "field '" + found->path + "'";
    throw UnwritableOutput("not writing " + file.string() + ": " + where + " " + found->problem);
  }
  return json.dump(indent) + "\n";
}

void check_csv_finite(std::string_view text, const std::filesystem::path& file) {
  std::size_t line = 1, column = 1, start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const bool end = i == text.size() || text[i] == '\n' || text[i] == ',';
    if (!end) continue;
    if (names_non_finite(text.substr(start, i - start)))
      throw UnwritableOutput("not writing " + file.string() + ": line " + std::to_string(line) +
                            ", field " + std::to_string(column) +
                            " is not a finite number (the computation behind it failed)");
    start = i + 1;
    if (i < text.size() && text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
}

}  // namespace nibrig::model::io
