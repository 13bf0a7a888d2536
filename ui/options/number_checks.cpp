#include "ui/options/number_checks.hpp"

#include <charconv>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>

#include <fmt/format.h>

namespace nibrig::ui {
namespace {

// Decimal only, as every file reader parses numbers (model/io/text_lines.hpp): hexadecimal, a
// leading '+' and trailing text are refused, the same for whole and fractional options.
std::optional<double> as_number(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end) return std::nullopt;
  return value;
}

// Subnormal numbers lose precision and turn divisions into infinities: no quantity of ours is that
// close to zero without being zero.
bool computable(double value) {
  return std::isfinite(value) && (value == 0.0 || std::fabs(value) >= DBL_MIN);
}

CLI::Validator number_check(std::string description, std::string expected,
                            std::function<bool(double)> accept) {
  return CLI::Validator(
      [expected, accept](std::string& text) -> std::string {
        const auto value = as_number(text);
        if (value && computable(*value) && accept(*value)) return {};
        return text + ": expected " + expected;
      },
      std::move(description));
}

std::string number_text(double value) { return fmt::format("{:g}", value); }

}  // namespace

CLI::Validator in_range(double low, double high, const std::string& what) {
  const std::string range = number_text(low) + " to " + number_text(high);
  return number_check(range, what + ", " + range,
                      [low, high](double v) { return v >= low && v <= high; });
}

CLI::Validator off_or_in_range(double low, double high, const std::string& what) {
  const std::string range = "0 or " + number_text(low) + " to " + number_text(high);
  return number_check(range, what + ", " + range,
                      [low, high](double v) { return v == 0 || (v >= low && v <= high); });
}

CLI::Validator stylus_metres(const std::string& what) {
  return number_check("metres, 0 to 1",
                      what + " in metres, > 0 and at most 1 (a stylus is centimetres long: "
                             "millimetres given as metres?)",
                      [](double v) { return v > 0 && v <= 1; });
}

CLI::Validator whole_in_range(long long low, long long high, const std::string& what) {
  const std::string range = std::to_string(low) + " to " + std::to_string(high);
  return CLI::Validator(
      [low, high, expected = what + ", a whole number from " + range](std::string& text) {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (error == std::errc() && stop == end && value >= low && value <= high)
          return std::string();
        return text + ": expected " + expected;
      },
      range);
}

CLI::Validator any_seed() { return whole_in_range(0, 4294967295LL, "a seed"); }

}  // namespace nibrig::ui
