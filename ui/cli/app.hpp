// The `nibrig` command line: builds the CLI11 parser with every subcommand and runs it. Errors
// become one line on stderr and a non-zero exit code.
#pragma once

namespace nibrig::ui::cli {

int run(int argc, char** argv);

}  // namespace nibrig::ui::cli
