// find_package(nibrig) from a project outside the tree: the dev component installed into a prefix
// of the test's own, tests/example_project configured and built against it alone (its compiler
// given only the prefix's headers), and the program it builds plays a catalog tool through the
// engine to the output the tree's own libraries give.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "model/io/catalog_file.hpp"
#include "rt/engine.hpp"
#include "rt/voice_builder.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::ui::cli {
namespace {

namespace fs = std::filesystem;
using nibrig::test::run_program;

struct Played {
  double rms = 0, peak = 0;
};

// What tests/example_project/play_a_tool.cpp renders, with the tree's libraries: the same stylus,
// the same stroke and seed.
Played play_in_process(const fs::path& catalog_file, const std::string& tool,
                       const std::string& surface) {
  const auto catalog = model::io::read_catalog(catalog_file);
  const auto pairing = std::find_if(catalog.pairings.begin(), catalog.pairings.end(), [&](auto& p) {
    return p.tool == tool && p.surface == surface && p.vibration;
  });
  model::modal::ModalModel stylus;
  for (double hz : {200.0, 900.0, 3000.0}) {
    const double omega = 2 * std::numbers::pi * hz;
    stylus.omega.push_back(omega);
    stylus.zeta.push_back(model::modal::rayleigh_damping_ratio(omega, 0.0, 1.25e-3));
    stylus.input.push_back(1.0);
    stylus.output.push_back(1.0);
  }
  rt::Engine engine{rt::EngineSettings{}};
  engine.load(0, rt::build_voice(tool + " on " + surface, stylus, pairing->vibration->spectrum,
                                 engine.internal_rate(), 1));
  engine.select(0);
  engine.attach(std::make_unique<rt::SweepStroke>());
  std::vector<float> block(64);
  double sum = 0;
  Played played;
  const std::size_t blocks = 3 * 48000 / block.size();
  for (std::size_t b = 0; b < blocks; ++b) {
    engine.render(block.data(), block.size());
    for (float x : block) {
      sum += static_cast<double>(x) * x;
      played.peak = std::max(played.peak, std::abs(static_cast<double>(x)));
    }
  }
  played.rms = std::sqrt(sum / static_cast<double>(blocks * block.size()));
  return played;
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
  const auto answer = nlohmann::json::parse(played.output.substr(played.output.find('{')));
  EXPECT_EQ(answer["frames"].get<std::size_t>(), 3u * 48000u);
  const auto expected = play_in_process(catalog, "DM851", "paperlike");
  ASSERT_GT(expected.rms, 0.0);
  // The same library code and seed; only the example's own sums are another compiler's, which may
  // contract or order them differently (1e-16 relative a sample), far under 1e-9.
  EXPECT_NEAR(answer["rms"].get<double>() / expected.rms, 1.0, 1e-9);
  EXPECT_NEAR(answer["peak"].get<double>() / expected.peak, 1.0, 1e-9);
  // A tool the catalog does not pair is refused with its name, not played as silence.
  const auto refused = run_program(
      {(example / "play_a_tool").string(), catalog.string(), "DM851", "no-such-surface"}, scratch);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.output.find("no-such-surface"), std::string::npos) << refused.output;
}

}  // namespace
}  // namespace nibrig::ui::cli
