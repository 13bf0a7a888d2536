// Typed access to the fields of a JSON file for the readers in model/io: every failure is a
// FormatError naming the file and the JSON path of the field (e.g. `pairings[3].vibration.mu`).
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace nibrig::model::io::json_fields {

// Parses a whole file; syntax errors name the line. An empty file, a file larger than
// kMaxJsonBytes and a key that appears twice in one object are errors.
inline constexpr std::size_t kMaxJsonBytes = std::size_t{256} << 20;
// Objects and arrays nested deeper than this are refused: nibrig's own files nest a few levels (a
// catalog's spectra are the deepest, 6), and a file nested 100,000 deep took gigabytes to parse.
inline constexpr std::size_t kMaxJsonDepth = 64;
nlohmann::json parse_file(const std::filesystem::path& file);
// The same checks on text already in memory (a pickled object's state); `file` names it in errors.
nlohmann::json parse_text(const std::string& text, const std::filesystem::path& file);

// "parent.key" and "parent[i]"; an empty parent gives "key".
std::string member_path(const std::string& parent, const std::string& key);
std::string element_path(const std::string& parent, std::size_t index);

// The place string used in errors: "field 'a.b[2]'".
std::string place(const std::string& path);

// Checks `value` (found at `path`) is an object / array, else throws "expected an object, found
// ...".
const nlohmann::json& as_object(const nlohmann::json& value, const std::filesystem::path& file,
                                const std::string& path);
const nlohmann::json& as_array(const nlohmann::json& value, const std::filesystem::path& file,
                               const std::string& path);

// A member of an object that must be present; "missing field" otherwise.
const nlohmann::json& member(const nlohmann::json& object, const std::string& key,
                             const std::filesystem::path& file, const std::string& parent);

std::string as_string(const nlohmann::json& value, const std::filesystem::path& file,
                      const std::string& path);
// A finite number of magnitude at most kMaxJsonMagnitude (JSON has no NaN, but a reader must not
// trust that; 1e300 is finite and still overflows the first square taken of it).
inline constexpr double kMaxJsonMagnitude = 1e15;
double as_number(const nlohmann::json& value, const std::filesystem::path& file,
                 const std::string& path);
// A number in [low, high]; `why` says what the range means ("a friction coefficient: no drawing
// tool's is near 10") and goes into the message.
double as_number_in(const nlohmann::json& value, const std::filesystem::path& file,
                    const std::string& path, double low, double high, const std::string& why);
// A whole number in [min, max].
long long as_integer(const nlohmann::json& value, const std::filesystem::path& file,
                     const std::string& path, long long min, long long max);
std::vector<double> as_number_array(const nlohmann::json& value, const std::filesystem::path& file,
                                    const std::string& path);
// Each element in [low, high], as as_number_in.
std::vector<double> as_number_array_in(const nlohmann::json& value,
                                       const std::filesystem::path& file, const std::string& path,
                                       double low, double high, const std::string& why);

// Shorthands for a required member of a given type.
// Checks the "format" and "version" members every file of ours opens with: the format name must
// match and the version must not be newer than this program's. Errors name the member.
void check_format_and_version(const nlohmann::json& object, const std::filesystem::path& file,
                              const std::string& format, long long newest_version);

std::string string_member(const nlohmann::json& object, const std::string& key,
                          const std::filesystem::path& file, const std::string& parent);
double number_member(const nlohmann::json& object, const std::string& key,
                     const std::filesystem::path& file, const std::string& parent);

}  // namespace nibrig::model::io::json_fields
