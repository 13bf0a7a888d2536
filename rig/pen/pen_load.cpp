#include "rig/pen/pen_load.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "rig/pen/pen_force.hpp"

namespace nibrig::rig::pen {

double parse_pen_load(const std::string& text) {
  const auto refuse = [&text](const std::string& why) -> std::invalid_argument {
    return std::invalid_argument("load '" + text + "': " + why);
  };
  std::string_view rest = text;
  while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.front())))
    rest.remove_prefix(1);
  while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.back())))
    rest.remove_suffix(1);
  const char* const expected =
      "expected a decimal number above 0 and a unit: g, kg, N or mN (e.g. \"200g\", \"1.5N\")";
  if (rest.empty() || rest.front() == '+') throw refuse(expected);
  double value = 0.0;
  const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), value);
  if (error != std::errc() || !std::isfinite(value)) throw refuse(expected);
  std::string_view unit(end, static_cast<std::size_t>(rest.data() + rest.size() - end));
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.front())))
    unit.remove_prefix(1);
  double newtons_per_unit = 0.0;
  if (unit == "g")
    newtons_per_unit = kStandardGravity / 1000.0;
  else if (unit == "kg")
    newtons_per_unit = kStandardGravity;
  else if (unit == "N")
    newtons_per_unit = 1.0;
  else if (unit == "mN")
    newtons_per_unit = 1e-3;
  else if (unit.empty())
    throw refuse("no unit: " + std::string(expected));
  else
    throw refuse("unknown unit '" + std::string(unit) + "': " + expected);
  if (!(value > 0.0)) throw refuse(expected);
  const double newtons = value * newtons_per_unit;
  if (newtons > kMaxPenForceN)
    throw refuse("expected at most " + std::to_string(static_cast<int>(kMaxPenForceN)) + " N (" +
                 std::to_string(static_cast<int>(kMaxPenForceN / kStandardGravity * 1000.0)) +
                 " g): no pen tip bears more");
  return newtons;
}

}  // namespace nibrig::rig::pen
