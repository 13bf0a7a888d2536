// `cmake --install` of this tree into a prefix of the test's own: the command, its assets, the
// defaults the build computed, its manual pages and completion, and the rig's udev rule land in
// the GNU directories, and the
// installed `nibrig` runs its demo from them, finding its assets and defaults beside its bin/
// rather than in the source tree it was built from.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "model/io/user_cache.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::ui::cli {
namespace {

namespace fs = std::filesystem;
using nibrig::test::read_json;
using nibrig::test::run_program;

TEST(Install, TheInstalledCommandRunsItsDemoFromItsOwnShareFolder) {
  const auto scratch = nibrig::test::scratch_dir("install");
  const auto prefix = scratch / "usr";
  const auto build = fs::path(NIBRIG_TEST_BINARY_DIR).parent_path();
  const auto installed = run_program(
      {"cmake", "--install", build.string(), "--prefix", prefix.string(), "--component", "command"},
      scratch);
  ASSERT_EQ(installed.exit_code, 0) << installed.output;
  const auto share = prefix / "share" / "nibrig";
  const fs::path nibrig = prefix / "bin" / "nibrig";
  EXPECT_TRUE(fs::is_regular_file(nibrig));
  EXPECT_TRUE(fs::is_regular_file(share / "assets" / "default_catalog.json"));
  EXPECT_FALSE(fs::exists(share / "assets" / "readme"));  // the README's pictures stay behind
  EXPECT_TRUE(fs::is_regular_file(prefix / "lib" / "udev" / "rules.d" / "70-nibrig-rig.rules"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "man" / "man1" / "nibrig-design-loop.1.gz"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "bash-completion" / "completions" / "nibrig"));

  const nibrig::test::ScopedCacheDir cache(scratch / "cache");
  const auto demo =
      run_program({nibrig.string(), "demo", "-o", (scratch / "demo").string()}, scratch);
  ASSERT_EQ(demo.exit_code, 0) << demo.output;
  EXPECT_TRUE(fs::is_regular_file(scratch / "demo" / "SUMMARY.json"));

  // The defaults the build computed, read from the installed share folder: nothing computed.
  if (!model::io::shipped_cache_dir().empty()) {
    const auto defaults = run_program(
        {nibrig.string(), "defaults", "--json", (scratch / "defaults.json").string()}, scratch);
    ASSERT_EQ(defaults.exit_code, 0) << defaults.output;
    const auto listed = read_json(scratch / "defaults.json")["defaults"];
    ASSERT_EQ(listed.size(), 5u);
    for (const auto& d : listed) {
      EXPECT_FALSE(d["computed"].get<bool>()) << d;
      EXPECT_EQ(fs::path(d["file"].get<std::string>()).parent_path(), share / "defaults") << d;
    }
  }

  // The Python package where Debian's python3 finds a prefix's packages, finding the same share
  // folder from its own place.
  const auto site = prefix / "lib" / "python3" / "dist-packages";
  if (fs::is_directory(build / "python" / "nibrig")) {
    const auto python = run_program({"cmake", "--install", build.string(), "--prefix",
                                     prefix.string(), "--component", "python"},
                                    scratch);
    ASSERT_EQ(python.exit_code, 0) << python.output;
    const auto imported = run_program({"env", "PYTHONPATH=" + site.string(),
                                       "LSAN_OPTIONS=detect_leaks=0", "/usr/bin/python3", "-c",
                                       "import nibrig, nibrig.measure; print(nibrig.__file__); "
                                       "print(nibrig.measure.bundled_catalog())"},
                                      scratch);
    ASSERT_EQ(imported.exit_code, 0) << imported.output;
    EXPECT_NE(imported.output.find((site / "nibrig" / "__init__.py").string()), std::string::npos)
        << imported.output;
    EXPECT_NE(imported.output.find((share / "assets" / "default_catalog.json").string()),
              std::string::npos)
        << imported.output;
  }

  // The panel, its menu entry (valid to desktop-file-validate) and the icon the entry names.
  if (fs::is_regular_file(build / "ui" / "panel" / "nibrig-panel")) {
    const auto panel = run_program(
        {"cmake", "--install", build.string(), "--prefix", prefix.string(), "--component", "panel"},
        scratch);
    ASSERT_EQ(panel.exit_code, 0) << panel.output;
    EXPECT_TRUE(fs::is_regular_file(prefix / "bin" / "nibrig-panel"));
    const auto entry = prefix / "share" / "applications" / "nibrig-panel.desktop";
    const auto valid = run_program({"desktop-file-validate", entry.string()}, scratch);
    EXPECT_EQ(valid.exit_code, 0) << valid.output;
    EXPECT_EQ(valid.output, "");
    // What it runs and shows are what was installed.
    std::ifstream in(entry);
    std::string exec, icon;
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("Exec=", 0) == 0) exec = line.substr(5);
      if (line.rfind("Icon=", 0) == 0) icon = line.substr(5);
    }
    EXPECT_TRUE(fs::is_regular_file(prefix / "bin" / exec)) << exec;
    EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "icons" / "hicolor" / "scalable" / "apps" /
                                    (icon + ".svg")))
        << icon;
  }

  // Its assets are the installed ones: without the installed catalog it names the installed path,
  // not falling back on the source tree's.
  fs::remove(share / "assets" / "default_catalog.json");
  const auto missing = run_program({nibrig.string(), "predict", "--design", "vero,tip=2mm",
                                    "--surface", "glass", "-o", (scratch / "p.json").string()},
                                   scratch);
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find((share / "assets" / "default_catalog.json").string()),
            std::string::npos)
      << missing.output;
}

}  // namespace
}  // namespace nibrig::ui::cli
