// How `nibrig` reports a command line it cannot use, the way git and cmake do: one line
// "nibrig: error: ..." on stderr and exit code 2, with the nearest subcommand for a misspelt one.
// The program's own failures (a bad file, a failed fit) stay exit code 1.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace nibrig::ui::cli {

inline constexpr int kUsageErrorExitCode = 2;

// The one of `names` closest to `typed` by edit distance, when close enough to be a slip (at most
// 2 edits, and fewer than half the letters); empty otherwise.
std::string nearest_name(const std::string& typed, const std::vector<std::string>& names);

// Prints the error for `e` thrown while parsing `app` and returns the exit code: 0 for --help and
// --version (CLI11 reports them as errors too), kUsageErrorExitCode otherwise.
int report_parse_error(CLI::App& app, const CLI::ParseError& e);

}  // namespace nibrig::ui::cli
