// What nibrig writes holds no NaN and no infinity: a computation that produced one has failed, and
// a file holding one is refused by the next reader (or, in JSON, silently turns into null).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>

namespace nibrig::model::io {

// Thrown instead of writing: "not writing FILE: field 'modes[2].frequency_hz' is not a finite
// number".
class UnwritableOutput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `json` as the text of `file` (indent as nlohmann's dump, then a final line break). Throws
// UnwritableOutput naming the first field that is NaN or infinite, or text that is not UTF-8.
std::string json_text(const nlohmann::json& json, const std::filesystem::path& file,
                      int indent = 2);

// Throws UnwritableOutput naming the line and column of the first field of a CSV text that reads
// nan or inf (as printf, iostreams and fmt print them, with any sign or case).
void check_csv_finite(std::string_view text, const std::filesystem::path& file);

}  // namespace nibrig::model::io
