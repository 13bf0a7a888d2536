// The manual pages and bash completion `nibrig docs` writes from its own parser, checked against
// what each command's --help lists (CLI11's formatter, not the generator): a page per command that
// groff reads without a warning and that gives every option, and a completion that offers exactly
// each command's subcommands and options.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::ui::cli {
namespace {

namespace fs = std::filesystem;
using nibrig::test::run_program;

struct Help {
  std::set<std::string> subcommands, long_options;
};

// A command's --help: the names under "Subcommands:" and every --option at the start of a line.
Help help_of(const std::vector<std::string>& words, const fs::path& scratch) {
  std::vector<std::string> args{NIBRIG_CLI_BINARY};
  args.insert(args.end(), words.begin(), words.end());
  args.push_back("--help");
  const auto run = run_program(args, scratch);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  Help h;
  std::istringstream lines(run.output);
  std::string line;
  bool in_subcommands = false;
  const std::regex option(R"(^  (?:-\w,)?(--[\w-]+))"), subcommand(R"(^  ([a-z][\w-]*)\s)");
  std::smatch m;
  while (std::getline(lines, line)) {
    if (line.rfind("Subcommands:", 0) == 0)
      in_subcommands = true;
    else if (!line.empty() && line[0] != ' ')
      in_subcommands = false;
    if (in_subcommands && std::regex_search(line, m, subcommand))
      h.subcommands.insert(m[1]);
    else if (std::regex_search(line, m, option))
      h.long_options.insert(m[1]);
  }
  return h;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string escaped(const std::string& option) {  // as roff needs a hyphen: \-
  std::string out;
  for (char c : option) out += c == '-' ? std::string("\\-") : std::string(1, c);
  return out;
}

std::set<std::string> completions(const fs::path& script, const std::vector<std::string>& words,
                                  const std::string& current, const fs::path& scratch) {
  std::string line = "source '" + script.string() + "'; COMP_WORDS=(nibrig";
  for (const auto& w : words) line += " '" + w + "'";
  line += " '" + current + "'); COMP_CWORD=" + std::to_string(words.size() + 1) +
          "; _nibrig; printf '%s\\n' \"${COMPREPLY[@]}\"";
  const auto run = run_program({"bash", "-c", line}, scratch);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  std::set<std::string> out;
  std::istringstream lines(run.output);
  for (std::string l; std::getline(lines, l);)
    if (!l.empty()) out.insert(l);
  return out;
}

TEST(ManualPages, EveryCommandHasAPageAndACompletionWithEveryOptionItsHelpLists) {
  const auto scratch = nibrig::test::scratch_dir("manual_pages");
  const auto man = scratch / "man", script = scratch / "nibrig.bash";
  const auto written = run_program(
      {NIBRIG_CLI_BINARY, "docs", "--man", man.string(), "--bash-completion", script.string()},
      scratch);
  ASSERT_EQ(written.exit_code, 0) << written.output;

  std::vector<std::vector<std::string>> pending{{}};
  std::size_t commands = 0;
  while (!pending.empty()) {
    const auto words = pending.back();
    pending.pop_back();
    ++commands;
    const Help help = help_of(words, scratch);
    std::string page_name = "nibrig";
    for (const auto& w : words) page_name += "-" + w;
    const auto page = man / (page_name + ".1");
    ASSERT_TRUE(fs::is_regular_file(page)) << page;
    const std::string text = text_of(page);
    // Names are listed as "-o,--output" (roff-escaped): the long one ends the list or precedes
    // another.
    for (const auto& option : help.long_options)
      EXPECT_TRUE(text.find(escaped(option) + "\\fR") != std::string::npos ||
                  text.find(escaped(option) + ",") != std::string::npos)
          << page_name << ": " << option;
    for (const auto& sub : help.subcommands) {
      EXPECT_NE(text.find("\\fB" + escaped(sub) + "\\fR"), std::string::npos)
          << page_name << ": " << sub;
      auto deeper = words;
      deeper.push_back(sub);
      pending.push_back(deeper);
    }
    // groff reads it with every warning on and says nothing.
    const auto groff = run_program({"groff", "-man", "-ww", "-z", page.string()}, scratch);
    EXPECT_EQ(groff.exit_code, 0) << groff.output;
    EXPECT_EQ(groff.output, "") << page_name;
    // The completion after these words: "--" offers exactly the help's long options, "" its
    // subcommands among what it offers.
    EXPECT_EQ(completions(script, words, "--", scratch), help.long_options) << page_name;
    if (!help.subcommands.empty()) {
      const auto offered = completions(script, words, "", scratch);
      for (const auto& sub : help.subcommands)
        EXPECT_TRUE(offered.contains(sub)) << page_name << ": " << sub;
    }
  }
  std::size_t pages = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(man)) ++pages;
  EXPECT_EQ(pages, commands);  // a page per command, none for the hidden `docs`
  EXPECT_GT(commands, 40u);
  // A word completes to the one command it starts.
  EXPECT_EQ(completions(script, {}, "des", scratch), std::set<std::string>{"design"});
  EXPECT_EQ(completions(script, {"space"}, "f", scratch).count("fit"), 1u);
}

}  // namespace
}  // namespace nibrig::ui::cli
