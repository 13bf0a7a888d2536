#include "model/io/json_fields.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

#include "model/io/bounded_read.hpp"
#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::io::json_fields {

namespace {

std::string describe(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::string:
      return "the string " + in_quotes(value.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float:
      return "the number " + value.dump();
    default:
      return "a value of another kind";
  }
}

// JSON lets a member name repeat, and nlohmann::json keeps the last: a session with
// "tool":"vero2","tool":"cryon" was measured as cryon. The parser's callback sees every key with
// its depth; this keeps the keys of each open object and the path to it, for the message.
class DuplicateKeys {
 public:
  explicit DuplicateKeys(const std::filesystem::path& file) : file_(file) {}

  bool operator()(int, nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        if (open_.size() >= kMaxJsonDepth)
          throw FormatError(file_, place(child_path()),
                            "nested more than " + std::to_string(kMaxJsonDepth) +
                                " objects or arrays deep; nibrig's files nest a few levels (a "
                                "catalog 6), so this is not one of them");
        open_.push_back({event == Event::object_start, {}, {}, 0, child_path()});
        break;
      case Event::key: {
        Container& object = open_.back();
        object.last_key = parsed.get<std::string>();
        if (!object.keys.insert(object.last_key).second)
          throw FormatError(file_, place(member_path(object.path, object.last_key)),
                            "the key " + in_quotes(object.last_key) +
                                " appears twice in one object; each member may be named once");
        break;
      }
      case Event::object_end:
      case Event::array_end:
        open_.pop_back();
        counted();
        break;
      case Event::value:
        counted();
        break;
    }
    return true;
  }

 private:
  struct Container {
    bool object;
    std::set<std::string> keys;
    std::string last_key;
    std::size_t elements;
    std::string path;
  };

  std::string child_path() const {
    if (open_.empty()) return "";
    const Container& parent = open_.back();
    return parent.object ? member_path(parent.path, parent.last_key)
                         : element_path(parent.path, parent.elements);
  }
  void counted() {
    if (!open_.empty() && !open_.back().object) ++open_.back().elements;
  }

  const std::filesystem::path& file_;
  std::vector<Container> open_;
};

}  // namespace

nlohmann::json parse_file(const std::filesystem::path& file) {
  return parse_text(
      read_bounded_file(file, kMaxJsonBytes, "a JSON file", "the bundled catalog is 1.3 MB"), file);
}

nlohmann::json parse_text(const std::string& text, const std::filesystem::path& file) {
  if (std::all_of(text.begin(), text.end(),
                  [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; })) {
    throw FormatError(file, "", "empty file: expected a JSON object");
  }
  try {
    return nlohmann::json::parse(text, DuplicateKeys(file));
  } catch (const nlohmann::json::parse_error& error) {
    const std::size_t byte = std::min<std::size_t>(error.byte, text.size());
    const std::size_t line =
        1 + static_cast<std::size_t>(
                std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(byte), '\n'));
    throw FormatError(file, line_place(line), std::string("invalid JSON: ") + error.what());
  } catch (const nlohmann::json::exception& error) {
    // A number beyond double range ("1e999") is out_of_range, not parse_error, and has no position.
    throw FormatError(file, "", std::string("invalid JSON: ") + error.what());
  }
}

std::string member_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string element_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string place(const std::string& path) { return path.empty() ? "" : "field '" + path + "'"; }

const nlohmann::json& as_object(const nlohmann::json& value, const std::filesystem::path& file,
                                const std::string& path) {
  if (!value.is_object())
    throw FormatError(file, place(path), "expected an object, found " + describe(value));
  return value;
}

const nlohmann::json& as_array(const nlohmann::json& value, const std::filesystem::path& file,
                               const std::string& path) {
  if (!value.is_array())
    throw FormatError(file, place(path), "expected a list, found " + describe(value));
  return value;
}

const nlohmann::json& member(const nlohmann::json& object, const std::string& key,
                             const std::filesystem::path& file, const std::string& parent) {
  as_object(object, file, parent);
  const auto it = object.find(key);
  if (it == object.end()) {
    throw FormatError(file, place(member_path(parent, key)), "missing field");
  }
  return *it;
}

std::string as_string(const nlohmann::json& value, const std::filesystem::path& file,
                      const std::string& path) {
  if (!value.is_string())
    throw FormatError(file, place(path), "expected a string, found " + describe(value));
  return value.get<std::string>();
}

namespace {
// A JSON number that is finite; the checks both number readers start with.
double finite_number(const nlohmann::json& value, const std::filesystem::path& file,
                     const std::string& path) {
  if (!value.is_number())
    throw FormatError(file, place(path), "expected a number, found " + describe(value));
  const double number = value.get<double>();
  if (!std::isfinite(number))
    throw FormatError(file, place(path), "expected a finite number, found " + value.dump());
  return number;
}
}  // namespace

double as_number(const nlohmann::json& value, const std::filesystem::path& file,
                 const std::string& path) {
  const double number = finite_number(value, file, path);
  if (std::fabs(number) > kMaxJsonMagnitude) {
    std::ostringstream message;
    message << "found " << value.dump() << ": beyond ±" << kMaxJsonMagnitude
            << ", where no quantity in nibrig's files is (is the file damaged?)";
    throw FormatError(file, place(path), message.str());
  }
  return number;
}

double as_number_in(const nlohmann::json& value, const std::filesystem::path& file,
                    const std::string& path, double low, double high, const std::string& why) {
  // The field's own range, not kMaxJsonMagnitude: it says more.
  const double number = finite_number(value, file, path);
  if (!(number >= low && number <= high)) {
    std::ostringstream message;
    message << "found " << value.dump() << ", expected " << low << " to " << high << " (" << why
            << ")";
    throw FormatError(file, place(path), message.str());
  }
  return number;
}

std::vector<double> as_number_array_in(const nlohmann::json& value,
                                       const std::filesystem::path& file, const std::string& path,
                                       double low, double high, const std::string& why) {
  as_array(value, file, path);
  std::vector<double> numbers;
  numbers.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i)
    numbers.push_back(as_number_in(value[i], file, element_path(path, i), low, high, why));
  return numbers;
}

long long as_integer(const nlohmann::json& value, const std::filesystem::path& file,
                     const std::string& path, long long min, long long max) {
  // Built piecewise: GCC 12 at -O3 warns falsely (-Wrestrict) on "[" + std::to_string(...).
  std::string range = "[";
  range.append(std::to_string(min)).append(", ").append(std::to_string(max)).append("]");
  // nlohmann keeps non-negative integers as unsigned and negative ones as signed.
  if (value.is_number_unsigned()) {
    const auto number = value.get<unsigned long long>();
    if (max < 0 || number > static_cast<unsigned long long>(max) ||
        static_cast<long long>(number) < min) {
      throw FormatError(file, place(path),
                        "expected a whole number in " + range + ", found " + value.dump());
    }
    return static_cast<long long>(number);
  }
  if (value.is_number_integer()) {
    const long long number = value.get<long long>();
    if (number < min || number > max) {
      throw FormatError(file, place(path),
                        "expected a whole number in " + range + ", found " + value.dump());
    }
    return number;
  }
  throw FormatError(file, place(path),
                    "expected a whole number in " + range + ", found " + describe(value));
}

std::vector<double> as_number_array(const nlohmann::json& value, const std::filesystem::path& file,
                                    const std::string& path) {
  as_array(value, file, path);
  std::vector<double> numbers;
  numbers.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i) {
    numbers.push_back(as_number(value[i], file, element_path(path, i)));
  }
  return numbers;
}

std::string string_member(const nlohmann::json& object, const std::string& key,
                          const std::filesystem::path& file, const std::string& parent) {
  return as_string(member(object, key, file, parent), file, member_path(parent, key));
}

double number_member(const nlohmann::json& object, const std::string& key,
                     const std::filesystem::path& file, const std::string& parent) {
  return as_number(member(object, key, file, parent), file, member_path(parent, key));
}

void check_format_and_version(const nlohmann::json& object, const std::filesystem::path& file,
                              const std::string& format, long long newest_version) {
  const std::string found = string_member(object, "format", file, "");
  if (found != format) {
    throw FormatError(file, place("format"),
                      "expected \"" + format + "\", found " + nlohmann::json(found).dump());
  }
  const long long version =
      as_integer(member(object, "version", file, ""), file, "version", 1, 1'000'000);
  if (version > newest_version) {
    throw FormatError(file, place("version"),
                      "expected version " + std::to_string(newest_version) +
                          " (this program's), found " + std::to_string(version));
  }
}

}  // namespace nibrig::model::io::json_fields
