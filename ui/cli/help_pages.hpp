// The command line's own help as a manual page per command and a bash completion script: written
// from the CLI11 tree the program parses with, so that neither is ever written twice.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace nibrig::ui::cli {

// Every visible command under `root` (root included), depth first, with its words after the
// program's name ({} for the root, {"design", "loop"}); hidden ones (an empty group) are left out.
struct CommandPath {
  const CLI::App* app;
  std::vector<std::string> words;
};
std::vector<CommandPath> visible_commands(const CLI::App& root);

// nibrig.1, nibrig-design.1, nibrig-design-loop.1...: the name and what it does, the synopsis,
// the description and footer, every visible option with its argument and help, the subcommands,
// and a SEE ALSO to the others. `version` goes in the header.
std::string man_page(const CommandPath& command, const std::string& version);
std::string man_page_name(const CommandPath& command);  // "nibrig-design-loop.1"

// `_nibrig` completing subcommands and options for the command the words so far name, files
// otherwise; registered with `complete -F _nibrig nibrig`.
std::string bash_completion(const CLI::App& root);

}  // namespace nibrig::ui::cli
