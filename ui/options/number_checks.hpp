// Checks for the numbers typed on a command line, shared by every command of both faces. Each check
// knows what the number means and its unit, so a refusal names the option, the value and what was
// expected: "--speed: -5: expected a speed in mm/s, >= 0 and finite". (CLI11's own Range lets NaN
// through.)
// Numbers are decimal, as in every file nibrig reads: hexadecimal and subnormal values are refused.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace nibrig::ui {

// `what` names the quantity with its unit ("a speed in mm/s", "a length in metres"). All of these
// refuse NaN, infinities and text; the checks run while the command line is parsed, before any
// command starts its work.
// low <= value <= high. Every quantity that sets a duration, a size or a rate takes a range that
// means something, so that neither 1e308 nor 1e-300 starts a run that never ends.
CLI::Validator in_range(double low, double high, const std::string& what);
// 0 (the option's "off") or low <= value <= high.
CLI::Validator off_or_in_range(double low, double high, const std::string& what);
// A length on a stylus or its test bar, in metres: > 0 and at most 1 m. Refused above, not warned
// about: the usual slip is millimetres typed where metres are meant, which is 1000 times too long
// and still gives plausible-looking modes (a 21 m "bar" rings at 0.004 Hz) that would be written to
// JSON and plots; every real stylus dimension is centimetres or less.
CLI::Validator stylus_metres(const std::string& what);
// A whole number in [low, high]: counts, indices, seeds (a fraction or exponent is refused too).
CLI::Validator whole_in_range(long long low, long long high, const std::string& what);
// Any seed an unsigned option holds (CLI11 would wrap "-1" around into a seed silently).
CLI::Validator any_seed();

}  // namespace nibrig::ui
