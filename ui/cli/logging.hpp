// Logging for the command line: spdlog to stderr, quiet by default, louder with -v.
#pragma once

namespace nibrig::ui::cli {

// verbosity: 0 = warnings and errors, 1 = info, 2 = debug.
void configure_logging(int verbosity);

}  // namespace nibrig::ui::cli
