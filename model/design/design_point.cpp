#include "model/design/design_point.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "model/io/text_lines.hpp"

namespace nibrig::model::design {

namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// The whole of `s` as a finite number, or nothing.
bool read_number(std::string_view s, double& value) {
  s = trimmed(s);
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  return error == std::errc{} && end == s.data() + s.size() && std::isfinite(value);
}

[[noreturn]] void refuse(std::string_view text, const std::string& what) {
  throw std::invalid_argument("design '" + std::string(text) + "': " + what);
}

std::string number(double x, int digits = 6) {
  std::ostringstream out;
  out << std::setprecision(digits) << x;
  return out.str();
}

std::string written(const DesignPoint& point, int digits) {
  std::string out;
  for (const auto& share : point.mix)
    out += share.material + ":" + number(share.fraction, digits) + ",";
  return out + "tip=" + number(point.tip_diameter_m * 1e3, digits) + "mm";
}

}  // namespace

double DesignPoint::fraction_of(const std::string& material) const {
  for (const auto& share : mix)
    if (share.material == material) return share.fraction;
  return 0.0;
}

void validate(const DesignPoint& point) {
  const std::string text = to_string(point);
  if (point.mix.empty()) refuse(text, "names no material");
  std::set<std::string> seen;
  double sum = 0.0;
  for (const auto& share : point.mix) {
    if (share.material.empty()) refuse(text, "a material without a name");
    if (!seen.insert(share.material).second) refuse(text, "names '" + share.material + "' twice");
    if (!(share.fraction >= 0.0 && share.fraction <= 1.0))
      refuse(text, "the fraction of '" + share.material + "' is " + number(share.fraction) +
                       ", expected 0 to 1");
    sum += share.fraction;
  }
  if (std::abs(sum - 1.0) > kMixSumTolerance)
    refuse(text, "the fractions add up to " + number(sum) + ", expected 1");
  if (!(std::isfinite(point.tip_diameter_m) && point.tip_diameter_m > 0))
    refuse(text, "the tip diameter must be a positive length (tip=<mm>mm)");
}

DesignPoint parse_design_point(std::string_view text) {
  DesignPoint point;
  bool tip_seen = false;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view entry = trimmed(text.substr(start, comma - start));
    start = comma + 1;
    if (entry.empty()) refuse(text, "an empty entry (two commas, or one at an end)");
    if (entry.substr(0, 4) == "tip=") {
      std::string_view value = trimmed(entry.substr(4));
      if (value.size() < 3 || value.substr(value.size() - 2) != "mm")
        refuse(text, "the tip is written tip=<number>mm, found " + io::in_quotes(entry));
      double mm = 0;
      if (!read_number(value.substr(0, value.size() - 2), mm) || !(mm > 0))
        refuse(text, "the tip diameter must be a positive number of mm, found '" +
                         std::string(entry) + "'");
      if (tip_seen) refuse(text, "gives the tip twice");
      tip_seen = true;
      point.tip_diameter_m = mm * 1e-3;
      continue;
    }
    MaterialShare share;
    const std::size_t colon = entry.find(':');
    share.material = catalog_material_name(trimmed(entry.substr(0, colon)));
    if (colon != std::string_view::npos && !read_number(entry.substr(colon + 1), share.fraction))
      refuse(text, "the fraction of '" + share.material + "' is not a number");
    if (share.fraction > 0.0 && share.fraction < kSmallestMixFraction)
      refuse(text, "the fraction of '" + share.material + "' is " + number(share.fraction) + ", below " +
                       number(kSmallestMixFraction) + ": the print sheet's whole per cent would show it as 0 % " +
                       "(give at least " + number(kSmallestMixFraction) + ", or 0 to leave it out)");
    if (share.fraction != 0.0) point.mix.push_back(std::move(share));
  }
  if (!tip_seen) refuse(text, "no tip diameter (add tip=<number>mm)");
  validate(point);
  return point;
}

std::string catalog_material_name(std::string_view typed) {
  // The material table's full names are aliases: a user who read `mechanics --material` help or
  // assets/materials.json types those, and "VeroClear" (datasheet) and the fitted
  // "VeroClear-Piovarci2018" are both the catalog's printed "vero".
  static const std::pair<const char*, const char*> kNames[] = {
      {"vero", "vero"},          {"veroclear", "vero"},    {"veroclear-piovarci2018", "vero"},
      {"dm95", "DM95"},          {"dm85", "DM85"},         {"teflon", "teflon"},
      {"teflon-taped", "teflon"}};
  std::string lower(typed);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const auto& [name, catalog] : kNames)
    if (lower == name) return catalog;
  return std::string(typed);
}

std::string to_string(const DesignPoint& point) { return written(point, 6); }

std::string label(const DesignPoint& point) { return written(point, 3); }

DesignPoint interpolate(const DesignPoint& a, const DesignPoint& b, double lambda) {
  if (!(lambda >= 0.0 && lambda <= 1.0))
    throw std::invalid_argument("interpolate: lambda " + number(lambda) + " is outside [0, 1]");
  DesignPoint point;
  std::vector<std::string> materials;
  for (const auto& s : a.mix) materials.push_back(s.material);
  for (const auto& s : b.mix)
    if (std::find(materials.begin(), materials.end(), s.material) == materials.end())
      materials.push_back(s.material);
  for (const auto& m : materials) {
    const double f = (1 - lambda) * a.fraction_of(m) + lambda * b.fraction_of(m);
    if (f > 0) point.mix.push_back({m, f});
  }
  point.tip_diameter_m = (1 - lambda) * a.tip_diameter_m + lambda * b.tip_diameter_m;
  return point;
}

}  // namespace nibrig::model::design
