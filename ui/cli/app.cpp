#include "ui/cli/app.hpp"

#include <CLI/CLI.hpp>
#include <iostream>

namespace nibrig::ui::cli {

int run(int argc, char** argv) {
  CLI::App app{"nibrig: perception-aware modelling of digital drawing tools"};
  app.require_subcommand(1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return 0;
}

}  // namespace nibrig::ui::cli
