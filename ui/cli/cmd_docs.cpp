// `nibrig docs --man DIR --bash-completion FILE`: the manual pages and the completion script,
// written from this command line (help_pages.hpp). Hidden: the build runs it for the install.
#include <memory>

#include "ui/cli/commands.hpp"
#include "ui/cli/help_pages.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {

void add_docs_command(CLI::App& app, std::shared_ptr<const GlobalOptions>) {
  struct Options {
    std::filesystem::path man, completion;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("docs", "Write the manual pages and the bash completion script");
  cmd->group("");  // hidden: the build's, not a user's
  cmd->add_option("--man", o->man, "Folder to write nibrig.1 and a page per command into");
  cmd->add_option("--bash-completion", o->completion,
                  "File to write the bash completion script to");
  cmd->callback([o, root = &app] {
    if (!o->man.empty()) {
      ensure_folder(o->man);
      for (const auto& command : visible_commands(*root))
        write_text_file(o->man / man_page_name(command),
                        man_page(command, std::string("nibrig ") + NIBRIG_VERSION));
    }
    if (!o->completion.empty()) write_text_file(o->completion, bash_completion(*root));
  });
}

}  // namespace nibrig::ui::cli
