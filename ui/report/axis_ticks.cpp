#include "ui/report/axis_ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace nibrig::ui::report::detail {

namespace {

// Advance widths of DejaVu Sans in cap heights, measured from pango's rendering (digits 0.83,
// lower case 0.75 on average, upper case 0.89, m/w/M/W about 1.3), rounded up.
double glyph_width(char32_t c) {
  if (c == ' ') return 0.45;
  if (c >= '0' && c <= '9') return 0.86;
  if (c == 'm' || c == 'w' || c == 'M' || c == 'W') return 1.32;
  if (c == 'i' || c == 'j' || c == 'l' || c == 'I' || c == 'f' || c == 't' || c == 'r') return 0.55;
  if (c >= 'a' && c <= 'z') return 0.82;
  if (c >= 'A' && c <= 'Z') return 1.0;
  if (c == '.' || c == ',' || c == ':' || c == ';' || c == '\'' || c == '!' || c == '|')
    return 0.45;
  if (c == '(' || c == ')' || c == '[' || c == ']' || c == '/' || c == '-') return 0.6;
  if (c < 0x80) return 1.0;
  return 1.15;  // Greek, symbols, the minus sign, ×: about as wide as a capital
}

// Decodes one UTF-8 code point starting at text[i] and advances i; invalid bytes count as one
// glyph.
char32_t next_code_point(std::string_view text, std::size_t& i) {
  const auto byte = static_cast<unsigned char>(text[i]);
  int extra = 0;
  char32_t c = byte;
  if (byte >= 0xF0) {
    extra = 3;
    c = byte & 0x07;
  } else if (byte >= 0xE0) {
    extra = 2;
    c = byte & 0x0F;
  } else if (byte >= 0xC0) {
    extra = 1;
    c = byte & 0x1F;
  }
  ++i;
  for (int k = 0; k < extra && i < text.size(); ++k, ++i) {
    c = (c << 6) | (static_cast<unsigned char>(text[i]) & 0x3F);
  }
  return c;
}

std::string replace_minus(std::string text) {
  std::string out;
  for (char ch : text) {
    if (ch == '-') {
      out += "\u2212";
    } else {
      out += ch;
    }
  }
  return out;
}

int decimals_for(double step) {
  return std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
}

bool spacing_ok(const std::vector<Tick>& ticks, double lo, double hi, double length,
                const LabelExtent& extent, double gap) {
  for (std::size_t i = 1; i < ticks.size(); ++i) {
    const double distance = (ticks[i].position - ticks[i - 1].position) / (hi - lo) * length;
    const double needed = 0.5 * (extent(ticks[i].label) + extent(ticks[i - 1].label)) + gap;
    if (distance < needed) return false;
  }
  return true;
}

// Ticks at k·step (k integer) inside [lo, hi], labelled as values (or, with `powers`, as 10^value).
std::vector<double> multiples_in(double lo, double hi, double step) {
  std::vector<double> out;
  const double tolerance = 1e-9 * step;
  const auto k0 = static_cast<long long>(std::ceil((lo - tolerance) / step));
  const auto k1 = static_cast<long long>(std::floor((hi + tolerance) / step));
  for (long long k = k0; k <= k1; ++k) out.push_back(static_cast<double>(k) * step);
  return out;
}

std::string power_of_ten_label(int exponent) {
  return "10#u" + replace_minus(std::to_string(exponent)) + "#d";
}

}  // namespace

double text_width_caps(std::string_view text) {
  double width = 0.0;
  double size = 1.0;  // shrinks inside super- and subscripts
  int level = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '#' && i + 1 < text.size()) {
      const char code = text[i + 1];
      if (code == 'u' || code == 'd') {
        level += code == 'u' ? 1 : -1;
        size = level == 0 ? 1.0 : 0.8;
        i += 2;
        continue;
      }
      if (code == 'g' && i + 2 < text.size()) {  // Greek letter
        width += size * 1.15;
        i += 3;
        continue;
      }
      if (code == '#') {
        width += size * 1.0;
        i += 2;
        continue;
      }
      if (code == '[' || code == '(') {  // a code point or Hershey glyph by number
        const auto close = text.find(code == '[' ? ']' : ')', i);
        width += size * 1.15;
        i = close == std::string_view::npos ? text.size() : close + 1;
        continue;
      }
      if (code == 'f' && i + 2 < text.size()) {  // font change
        i += 3;
        continue;
      }
      if (code == '-' || code == '+') {  // over- and underline toggles
        i += 2;
        continue;
      }
    }
    width += size * glyph_width(next_code_point(text, i));
  }
  return width;
}

std::string format_tick(double value, double step, double magnitude) {
  if (std::abs(value) < 1e-9 * step) value = 0.0;
  char buffer[64];
  const bool scientific = magnitude >= 1e5 || magnitude < 1e-3;
  if (!scientific) {
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals_for(step), value);
    return replace_minus(buffer);
  }
  if (value == 0.0) return "0";
  const int exponent = static_cast<int>(std::floor(std::log10(magnitude) + 1e-9));
  const double scale = std::pow(10.0, exponent);
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals_for(step / scale), value / scale);
  return replace_minus(buffer) + "\u00d7" + power_of_ten_label(exponent);
}

AxisTicks linear_ticks(double lo, double hi, double length, const LabelExtent& extent, double gap) {
  const double span = hi - lo;
  const double magnitude = std::max(std::abs(lo), std::abs(hi));
  const int e0 = static_cast<int>(std::floor(std::log10(span))) - 2;
  std::optional<AxisTicks> fallback;
  for (int e = e0; e <= e0 + 4; ++e) {
    for (int m : {1, 2, 5}) {
      const double step = m * std::pow(10.0, e);
      if (step < span / 15.0) continue;  // more labels than anyone reads
      AxisTicks ticks;
      for (double v : multiples_in(lo, hi, step)) {
        ticks.major.push_back({v, format_tick(v, step, magnitude)});
      }
      if (ticks.major.size() < 2) {
        return fallback ? *fallback : ticks;  // larger steps only give fewer labels
      }
      const int sub = m == 2 ? 4 : 5;
      const double minor_step = step / sub;
      const auto minors = multiples_in(lo, hi, minor_step);
      const auto k0 = static_cast<long long>(std::ceil((lo - 1e-9 * minor_step) / minor_step));
      for (std::size_t i = 0; i < minors.size(); ++i) {
        if ((k0 + static_cast<long long>(i)) % sub != 0) ticks.minor.push_back(minors[i]);
      }
      if (spacing_ok(ticks.major, lo, hi, length, extent, gap)) return ticks;
      fallback = std::move(ticks);
    }
  }
  return fallback ? *fallback : AxisTicks{};
}

AxisTicks log_ticks(double lo_log10, double hi_log10, double length, const LabelExtent& extent,
                    double gap) {
  const double tolerance = 1e-9;
  const auto first_decade = static_cast<int>(std::floor(lo_log10));
  const auto last_decade = static_cast<int>(std::ceil(hi_log10));
  const auto inside = [&](double p) {
    return p >= lo_log10 - tolerance && p <= hi_log10 + tolerance;
  };

  // Decades, every `every`-th labelled; the ones between and (for single steps) 2..9 as minor
  // ticks.
  const auto decades = [&](int every) {
    AxisTicks ticks;
    for (int k = first_decade; k <= last_decade; ++k) {
      if (!inside(k)) continue;
      if (k % every == 0) {
        ticks.major.push_back({static_cast<double>(k), power_of_ten_label(k)});
      } else {
        ticks.minor.push_back(k);
      }
    }
    if (every == 1 && hi_log10 - lo_log10 <= 8.0) {
      for (int k = first_decade - 1; k <= last_decade; ++k) {
        for (int m = 2; m <= 9; ++m) {
          const double p = k + std::log10(m);
          if (inside(p)) ticks.minor.push_back(p);
        }
      }
    }
    return ticks;
  };
  // Multiples m·10^k, the listed ones labelled and the others (of 1..9) minor.
  const auto multiples = [&](const std::vector<int>& labelled) {
    AxisTicks ticks;
    for (int k = first_decade - 1; k <= last_decade; ++k) {
      for (int m = 1; m <= 9; ++m) {
        const double p = k + std::log10(m);
        if (!inside(p)) continue;
        if (std::find(labelled.begin(), labelled.end(), m) != labelled.end()) {
          const double value = m * std::pow(10.0, k);
          ticks.major.push_back({p, format_tick(value, std::pow(10.0, k), value)});
        } else {
          ticks.minor.push_back(p);
        }
      }
    }
    return ticks;
  };
  const auto fits = [&](const AxisTicks& t, std::size_t at_least) {
    return t.major.size() >= at_least &&
           spacing_ok(t.major, lo_log10, hi_log10, length, extent, gap);
  };

  // Linear steps of the values themselves, placed at their logarithms: for ranges under a decade.
  const auto linear_values = [&]() {
    const double lo = std::pow(10.0, lo_log10);
    const double hi = std::pow(10.0, hi_log10);
    const double span = hi - lo;
    const int e0 = static_cast<int>(std::floor(std::log10(span))) - 2;
    AxisTicks best;
    for (int e = e0; e <= e0 + 4; ++e) {
      for (int m : {1, 2, 5}) {
        const double step = m * std::pow(10.0, e);
        if (step < span / 15.0) continue;
        AxisTicks t;
        for (double v : multiples_in(lo, hi, step)) {
          if (v > 0.0) t.major.push_back({std::log10(v), format_tick(v, step, hi)});
        }
        if (t.major.size() < 2) return best;
        best = t;
        if (spacing_ok(t.major, lo_log10, hi_log10, length, extent, gap)) return t;
      }
    }
    return best;
  };

  for (int every : {1, 2, 3, 5, 10, 20}) {
    auto t = decades(every);
    if (fits(t, 3)) return t;
    if (t.major.size() < 3) break;
  }
  if (auto t = multiples({1, 2, 5}); fits(t, 3)) return t;
  if (hi_log10 - lo_log10 <= 1.0) {
    if (auto t = linear_values(); fits(t, 2)) return t;
  }
  if (auto t = multiples({1, 2, 3, 4, 5, 6, 7, 8, 9}); fits(t, 2)) return t;
  if (auto t = decades(1); fits(t, 2)) return t;
  if (auto t = multiples({1, 2, 5}); fits(t, 2)) return t;
  return linear_values();
}

}  // namespace nibrig::ui::report::detail
