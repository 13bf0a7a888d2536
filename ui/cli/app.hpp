// The `nibrig` command line: builds the CLI11 parser with every subcommand and runs it. Errors
// become one line on stderr and a non-zero exit code.
#pragma once

#include <stdexcept>

namespace nibrig::ui::cli {

int run(int argc, char** argv);

// Thrown by a command that caught Ctrl-C and kept what it had (a capture's session): the reason is
// printed and the exit status is 130, as for every command Ctrl-C stops.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};
inline constexpr int kInterruptedExitCode = 130;  // 128 + SIGINT, what a shell reports

}  // namespace nibrig::ui::cli
