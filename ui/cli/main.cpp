// Entry point of the `nibrig` command: everything lives in ui/cli/app.cpp so that tests can run it.
#include "ui/cli/app.hpp"

int main(int argc, char** argv) { return nibrig::ui::cli::run(argc, argv); }
