// Entry point of the `nibrig` command; the command itself is run() in ui/cli/app.cpp.
#include "ui/cli/app.hpp"

int main(int argc, char** argv) { return nibrig::ui::cli::run(argc, argv); }
