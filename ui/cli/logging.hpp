// Logging for the command line: spdlog to stderr, quiet by default, louder with -v.
#pragma once

namespace nibrig::ui::cli {

// -q: errors only (no warnings, no progress).
inline constexpr int kQuiet = -1;

// verbosity: kQuiet, 0 = warnings and errors, 1 = info, 2 = debug.
void configure_logging(int verbosity);

// Whether warnings are shown, which is also whether progress is (not with -q).
bool warnings_shown();

}  // namespace nibrig::ui::cli
