#include "ui/cli/help_pages.hpp"

#include <set>
#include <sstream>

namespace nibrig::ui::cli {

namespace {

bool visible(const CLI::App& app) { return !app.get_group().empty(); }

void walk(const CLI::App& app, std::vector<std::string> words, std::vector<CommandPath>& out) {
  out.push_back({&app, words});
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (visible(*sub)) {
      auto deeper = words;
      deeper.push_back(sub->get_name());
      walk(*sub, deeper, out);
    }
}

std::string joined(const std::vector<std::string>& words, const std::string& between) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : between) + w;
  return out;
}

// Text as roff reads it: backslashes and hyphens escaped, a line starting with . or ' guarded.
std::string roff(const std::string& text) {
  std::string out;
  bool line_start = true;
  for (const char c : text) {
    if (line_start && (c == '.' || c == '\'')) out += "\\&";
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else
      out += c;
    line_start = c == '\n';
  }
  return out;
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

std::vector<const CLI::Option*> visible_options(const CLI::App& app) {
  std::vector<const CLI::Option*> out;
  for (const CLI::Option* o :
       app.get_options([](const CLI::Option* o) { return !o->get_group().empty(); }))
    out.push_back(o);
  return out;
}

}  // namespace

std::vector<CommandPath> visible_commands(const CLI::App& root) {
  std::vector<CommandPath> out;
  walk(root, {}, out);
  return out;
}

std::string man_page_name(const CommandPath& command) {
  return joined(
             [&] {
               std::vector<std::string> w{"nibrig"};
               w.insert(w.end(), command.words.begin(), command.words.end());
               return w;
             }(),
             "-") +
         ".1";
}

std::string man_page(const CommandPath& command, const std::string& version) {
  const CLI::App& app = *command.app;
  const std::string page = man_page_name(command);
  const std::string title = page.substr(0, page.size() - 2);
  std::string upper = title;
  for (auto& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::string invocation = joined(
      [&] {
        std::vector<std::string> w{"nibrig"};
        w.insert(w.end(), command.words.begin(), command.words.end());
        return w;
      }(),
      " ");
  std::ostringstream out;
  out << ".TH " << roff(upper) << " 1 \"\" \"" << roff(version) << "\" \"nibrig manual\"\n";
  out << ".SH NAME\n" << roff(title) << " \\- " << roff(first_line(app.get_description())) << "\n";
  const auto subs = app.get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); });
  out << ".SH SYNOPSIS\n.B " << roff(invocation) << "\n[\\fIOPTIONS\\fR]"
      << (subs.empty() ? "" : " \\fICOMMAND\\fR") << "\n";
  out << ".SH DESCRIPTION\n" << roff(app.get_description()) << "\n";
  if (!app.get_footer().empty()) out << ".PP\n" << roff(app.get_footer()) << "\n";
  out << ".SH OPTIONS\n";
  for (const CLI::Option* o : visible_options(app)) {
    out << ".TP\n\\fB" << roff(o->get_name(false, true)) << "\\fR";
    if (o->get_type_size() != 0 && !o->get_type_name().empty())
      out << " \\fI" << roff(o->get_type_name()) << "\\fR";
    out << "\n" << roff(o->get_description()) << "\n";
  }
  if (!subs.empty()) {
    out << ".SH COMMANDS\n";
    for (const CLI::App* s : subs) {
      auto words = command.words;
      words.push_back(s->get_name());
      const std::string sub_page = man_page_name({s, words});
      out << ".TP\n\\fB" << roff(s->get_name()) << "\\fR\n"
          << roff(first_line(s->get_description())) << " (\\fB"
          << roff(sub_page.substr(0, sub_page.size() - 2)) << "\\fR(1))\n";
    }
  }
  out << ".SH SEE ALSO\n\\fBnibrig\\fR(1)\n";
  return out.str();
}

std::string bash_completion(const CLI::App& root) {
  const auto commands = visible_commands(root);
  std::ostringstream out;
  out << "# bash completion for nibrig, written from its command line (nibrig docs)\n"
      << "_nibrig() {\n"
      << "  local cur=${COMP_WORDS[COMP_CWORD]} path='' i words\n"
      << "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
      << "    case \"$path ${COMP_WORDS[i]}\" in\n";
  std::string paths;
  for (const auto& c : commands)
    if (!c.words.empty())
      paths += std::string(paths.empty() ? "" : "|") + "' " + joined(c.words, " ") + "'";
  out << "      " << paths << ") path=\"$path ${COMP_WORDS[i]}\" ;;\n"
      << "    esac\n  done\n  case \"$path\" in\n";
  for (const auto& c : commands) {
    std::set<std::string> words;
    for (const CLI::App* s :
         c.app->get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); }))
      words.insert(s->get_name());
    for (const CLI::Option* o : visible_options(*c.app)) {
      for (const auto& n : o->get_lnames()) words.insert("--" + n);
      for (const auto& n : o->get_snames()) words.insert("-" + n);
    }
    out << "    '" << (c.words.empty() ? "" : " " + joined(c.words, " ")) << "') words='"
        << joined({words.begin(), words.end()}, " ") << "' ;;\n";
  }
  out << "  esac\n"
      << "  if [[ $cur == -* || $COMP_CWORD -eq 1 ]]; then\n"
      << "    COMPREPLY=($(compgen -W \"$words\" -- \"$cur\"))\n"
      << "  else\n"
      << "    COMPREPLY=($(compgen -W \"$words\" -- \"$cur\") $(compgen -f -- \"$cur\"))\n"
      << "  fi\n"
      << "}\n"
      << "complete -o filenames -F _nibrig nibrig\n";
  return out.str();
}

}  // namespace nibrig::ui::cli
