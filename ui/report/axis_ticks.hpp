// Axis ticks and their labels for report figures, and an estimate of how wide a label renders, so
// that a layout can reserve room for text before PLplot draws it (PLplot does not export its own
// string-length query).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace nibrig::ui::report::detail {

// Width of text in multiples of its cap height (PLplot's character height) when pango draws it in
// DejaVu Sans, the usual "Sans". Errs wide, so that reserved space is never short. Understands the
// PLplot escapes used in labels (#u, #d, #g, ##, #[0x...]).
double text_width_caps(std::string_view text);

struct Tick {
  double position;  // plot coordinate: the value, or log10 of it on a log axis
  std::string label;
};

struct AxisTicks {
  std::vector<Tick> major;    // labelled
  std::vector<double> minor;  // unlabelled, plot coordinates
};

// How much of the axis a label takes up along the axis, in the units of `length`.
using LabelExtent = std::function<double(const std::string&)>;

// Ticks at 1, 2 or 5 × 10^k steps over [lo, hi] (lo < hi), as dense as possible while neighbouring
// labels stay `gap` apart on an axis `length` long, with at least two labels.
AxisTicks linear_ticks(double lo, double hi, double length, const LabelExtent& extent, double gap);

// Ticks for a logarithmic axis given as [log10 lo, log10 hi]: decades when the range spans several,
// otherwise 1-2-5 or 1-to-9 multiples of the decades, otherwise linear steps in the values.
AxisTicks log_ticks(double lo_log10, double hi_log10, double length, const LabelExtent& extent,
                    double gap);

// A tick value written with as many decimals as the step needs, a true minus sign, and ×10^k
// (PLplot superscript escapes) for very large or very small magnitudes.
std::string format_tick(double value, double step, double magnitude);

}  // namespace nibrig::ui::report::detail
