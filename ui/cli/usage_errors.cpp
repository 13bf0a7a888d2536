#include "ui/cli/usage_errors.hpp"

#include <algorithm>
#include <cstdio>

namespace nibrig::ui::cli {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The innermost subcommand the command line reached: a misspelt word is one of its subcommands.
CLI::App* innermost(CLI::App* app) {
  for (CLI::App* sub : app->get_subcommands())
    if (sub->parsed()) return innermost(sub);
  return app;
}

// A word where a command was expected, named with the nearest command, or with the commands there
// are when none is near; empty when the line went wrong otherwise.
std::string suggestion(CLI::App& app) {
  CLI::App* where = innermost(&app);
  const auto extras = where->remaining();
  std::vector<std::string> names;
  for (const CLI::App* sub : where->get_subcommands({})) names.push_back(sub->get_name());
  if (extras.empty() || names.empty() || extras.front().rfind("-", 0) == 0) return "";
  const std::string prefix = where == &app ? "" : where->get_name() + " ";
  const std::string near = nearest_name(extras.front(), names);
  if (!near.empty()) return "'" + extras.front() + "' is not a command; did you mean '" + near + "'?";
  std::string all;
  for (const auto& name : names) all += (all.empty() ? "" : ", ") + name;
  return "'" + extras.front() + "' is not a " + (prefix.empty() ? "" : prefix) + "command; the commands are: " + all;
}

}  // namespace

std::string nearest_name(const std::string& typed, const std::vector<std::string>& names) {
  std::string best;
  std::size_t best_distance = 3;
  for (const auto& name : names) {
    const std::size_t d = edit_distance(typed, name);
    if (d < best_distance && 2 * d < std::max(typed.size(), name.size())) {
      best = name;
      best_distance = d;
    }
  }
  return best;
}

int report_parse_error(CLI::App& app, const CLI::ParseError& e) {
  const std::string hint = suggestion(app);
  // `nibrig frobnicate --help` is no request for the top-level help: the word is the error.
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success) && hint.empty()) return app.exit(e);
  std::fprintf(stderr, "nibrig: error: %s\n", hint.empty() ? e.what() : hint.c_str());
  return kUsageErrorExitCode;
}

}  // namespace nibrig::ui::cli
