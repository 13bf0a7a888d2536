// find_package(nibrig) from a project outside the tree: the dev component installed into a prefix
// of the test's own, tests/example_project configured and built against it alone (its compiler
// given only the prefix's headers), and the program it builds plays a catalog tool through the
// engine to the output the tree's own libraries give.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::ui::cli {
namespace {

namespace fs = std::filesystem;
using nibrig::test::run_program;

// play_a_tool's answer: {"frames": …, "rms": …, "peak": …}.
nlohmann::json answer_of(const nibrig::test::ProgramRun& run) {
  return nlohmann::json::parse(run.output.substr(run.output.find('{')));
}

TEST(LibraryInstall, AProjectOutsideTheTreeBuildsAgainstFindPackageAndPlaysATool) {
  const auto scratch = nibrig::test::scratch_dir("library_install");
  const auto prefix = scratch / "usr";
  const auto build = fs::path(NIBRIG_TEST_BINARY_DIR).parent_path();
  const fs::path source = NIBRIG_SOURCE_DIR;
  const auto installed = run_program(
      {"cmake", "--install", build.string(), "--prefix", prefix.string(), "--component", "dev"},
      scratch);
  ASSERT_EQ(installed.exit_code, 0) << installed.output;
  EXPECT_TRUE(fs::is_regular_file(prefix / "include" / "nibrig" / "rt" / "engine.hpp"));

  // The example's build sees the prefix and the system, never the source or build tree.
  const auto example = scratch / "example";
  const auto configured =
      run_program({"cmake", "-S", (source / "tests" / "example_project").string(), "-B",
                   example.string(), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                   "-DCMAKE_PREFIX_PATH=" + prefix.string(), "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON"},
                  scratch);
  ASSERT_EQ(configured.exit_code, 0) << configured.output;
  const auto built = run_program({"cmake", "--build", example.string()}, scratch);
  ASSERT_EQ(built.exit_code, 0) << built.output;
  const auto commands = nlohmann::json::parse(std::ifstream(example / "compile_commands.json"));
  ASSERT_EQ(commands.size(), 1u);
  std::istringstream words(commands[0]["command"].get<std::string>());
  std::vector<std::string> includes;
  for (std::string word, previous; words >> word; previous = word) {
    if (previous == "-isystem" || previous == "-I") includes.push_back(word);
    if (word.rfind("-I", 0) == 0 && word.size() > 2) includes.push_back(word.substr(2));
  }
  EXPECT_NE(std::find(includes.begin(), includes.end(), (prefix / "include" / "nibrig").string()),
            includes.end());
  for (const auto& dir : includes)  // the prefix's, else the system's: never the trees'
    EXPECT_TRUE(dir.rfind(prefix.string(), 0) == 0 || dir.rfind("/usr/", 0) == 0) << dir;

  const auto catalog = source / "assets" / "default_catalog.json";
  const auto played = run_program(
      {(example / "play_a_tool").string(), catalog.string(), "DM851", "paperlike"}, scratch);
  ASSERT_EQ(played.exit_code, 0) << played.output;
  const auto answer = answer_of(played);
  EXPECT_EQ(answer["frames"].get<std::size_t>(), 3u * 48000u);
  // The same program built in the tree with the tree's libraries (tests/CMakeLists.txt).
  const auto in_tree =
      run_program({NIBRIG_EXAMPLE_IN_TREE, catalog.string(), "DM851", "paperlike"}, scratch);
  ASSERT_EQ(in_tree.exit_code, 0) << in_tree.output;
  const auto expected = answer_of(in_tree);
  ASSERT_GT(expected["rms"].get<double>(), 0.0);
  // The same library code and seed; only the example's own sums are another compiler's, which may
  // contract or order them differently (1e-16 relative a sample), far under 1e-9.
  for (const char* figure : {"rms", "peak"})
    EXPECT_NEAR(answer[figure].get<double>() / expected[figure].get<double>(), 1.0, 1e-9) << figure;
  // A tool the catalog does not pair is refused with its name, not played as silence.
  const auto refused = run_program(
      {(example / "play_a_tool").string(), catalog.string(), "DM851", "no-such-surface"}, scratch);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.output.find("no-such-surface"), std::string::npos) << refused.output;
}

}  // namespace
}  // namespace nibrig::ui::cli
