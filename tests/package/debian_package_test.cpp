// The Debian packages of cmake/Package.cmake as a user gets them: cpack builds them from this
// tree, lintian finds no error in them, and apt installs them, with only what they declare pulled
// from Debian's archive, into a fresh Debian 12 root (mmdebstrap), where the installed `nibrig
// demo` writes its report and the installed Python module imports, with neither the source tree
// nor the build tree reachable from inside.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_program.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::package {
namespace {

namespace fs = std::filesystem;
using nibrig::test::run_program;

nlohmann::json read_json_file(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The mount points at or below `dir`: a root whose mounts were left behind (a killed mmdebstrap)
// must not be removed, or the removal would reach through them into the host's files.
std::vector<std::string> mounts_under(const fs::path& dir) {
  std::ifstream in("/proc/self/mountinfo");
  std::vector<std::string> found;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string id, parent, device, root, mount_point;
    fields >> id >> parent >> device >> root >> mount_point;
    if (mount_point.rfind(dir.string(), 0) == 0) found.push_back(mount_point);
  }
  return found;
}

// The fresh root is 700 MB: removed after the test, unless something is still mounted in it.
struct RootRemover {
  fs::path root;
  ~RootRemover() {
    if (mounts_under(root).empty()) fs::remove_all(root);
  }
};

// A command run inside the root as a user would run it there: a clean environment, so that none
// of the test's (NIBRIG_CACHE, LSAN_OPTIONS pointing into the build tree) leaks in.
nibrig::test::ProgramRun in_root(const fs::path& root, std::vector<std::string> command,
                                 const fs::path& scratch) {
  std::vector<std::string> args = {
      "env",    "-i",         "PATH=/usr/sbin:/usr/bin:/sbin:/bin", "HOME=/root", "LC_ALL=C.UTF-8",
      "chroot", root.string()};
  args.insert(args.end(), command.begin(), command.end());
  return run_program(args, scratch);
}

std::string control_field(const fs::path& deb, const std::string& field, const fs::path& scratch) {
  auto run = run_program({"dpkg-deb", "--field", deb.string(), field}, scratch);
  while (!run.output.empty() && run.output.back() == '\n') run.output.pop_back();
  return run.output;
}

TEST(DebianPackages, InstallIntoAFreshRootAndRunFromTheInstalledFilesAlone) {
  if (::geteuid() != 0) {
    GTEST_SKIP() << "needs root: mmdebstrap --mode=root and chroot build and enter the fresh "
                    "Debian root (run the test job as root)";
  }
  const auto scratch = nibrig::test::scratch_dir("debian_package");
  const auto build = fs::path(NIBRIG_TEST_BINARY_DIR).parent_path();
  const auto debs = scratch / "debs";

  const auto packed = run_program(
      {"cpack", "--config", (build / "CPackConfig.cmake").string(), "-B", debs.string()}, scratch);
  ASSERT_EQ(packed.exit_code, 0) << packed.output;
  const std::string version = NIBRIG_VERSION;
  const auto arch = run_program({"dpkg", "--print-architecture"}, scratch).output.substr(0, 5);
  const auto command = debs / ("nibrig_" + version + "_" + arch + ".deb");
  const auto panel = debs / ("nibrig-panel_" + version + "_" + arch + ".deb");
  const auto python = debs / ("python3-nibrig_" + version + "_" + arch + ".deb");
  for (const auto& deb : {command, panel, python}) ASSERT_TRUE(fs::is_regular_file(deb)) << deb;

  // The libraries each links, found by dpkg-shlibdeps in the binaries; the panel and the module
  // need the command's data, of the same version.
  EXPECT_NE(control_field(command, "Depends", scratch).find("libc6 (>="), std::string::npos);
  EXPECT_NE(control_field(command, "Depends", scratch).find("libgmsh"), std::string::npos);
  for (const auto& deb : {panel, python}) {
    EXPECT_EQ(control_field(deb, "Depends", scratch).rfind("nibrig (= " + version + ")", 0), 0u)
        << control_field(deb, "Depends", scratch);
  }

  // lintian: no error, other than those overridden in a package with its reason.
  const auto lint = run_program(
      {"lintian", "--fail-on", "error", command.string(), panel.string(), python.string()},
      scratch);
  EXPECT_EQ(lint.exit_code, 0) << lint.output;
  EXPECT_EQ(lint.output.find("\nE: "), std::string::npos) << lint.output;
  EXPECT_NE(lint.output.rfind("E: ", 0), 0u) << lint.output;

  // The root: Debian 12 with apt (the "apt" variant), then apt installs the three files and
  // whatever they depend on from the archive, recommends left out. The host's downloaded packages
  // are hard-linked into the root's cache first, so that apt fetches only what the host lacks.
  const auto root = scratch / "root";
  RootRemover remover{root};
  const auto made = run_program(
      {"mmdebstrap", "--variant=apt", "--mode=root",
       "--setup-hook=mkdir -p \"$1\"/var/cache/apt/archives && find /var/cache/apt/archives "
       "-maxdepth 1 -name '*.deb' -exec cp -l -t \"$1\"/var/cache/apt/archives {} + 2>/dev/null "
       "|| true",
       "--customize-hook=mkdir -p \"$1\"/tmp/nibrig-debs && cp " + command.string() + " " +
           panel.string() + " " + python.string() + " \"$1\"/tmp/nibrig-debs/",
       "--customize-hook=chroot \"$1\" env DEBIAN_FRONTEND=noninteractive sh -c 'apt-get install "
       "-y --no-install-recommends /tmp/nibrig-debs/*.deb'",
       "bookworm", root.string()},
      scratch);
  ASSERT_EQ(made.exit_code, 0) << made.output;

  // Nothing of this machine's trees inside: the source and build folders are not there.
  const auto source = fs::path(NIBRIG_SOURCE_DIR);
  const auto outside = [&] {
    EXPECT_FALSE(fs::exists(root / source.relative_path())) << source;
    EXPECT_FALSE(fs::exists(root / build.relative_path())) << build;
  };
  outside();

  // The installed command is the one a user builds, without the tests' LeakSanitizer.
  const auto symbols = run_program({"nm", "-D", (root / "usr/bin/nibrig").string()}, scratch);
  ASSERT_EQ(symbols.exit_code, 0) << symbols.output;
  EXPECT_EQ(symbols.output.find("__lsan"), std::string::npos);

  const auto demo = in_root(root, {"/usr/bin/nibrig", "demo", "-o", "/root/demo"}, scratch);
  ASSERT_EQ(demo.exit_code, 0) << demo.output;
  const auto summary = read_json_file(root / "root/demo/SUMMARY.json");
  EXPECT_EQ(summary["catalog"], "/usr/share/nibrig/assets/default_catalog.json") << summary;
  EXPECT_EQ(summary["render"]["sample_rate_hz"].get<double>(), 48000.0) << summary;
  EXPECT_GT(summary["render"]["loudest_rms_m_s2"].get<double>(), 0.0) << summary;

  // The module finds the installed catalog beside it, and reads all of it.
  const auto imported =
      in_root(root,
              {"/usr/bin/python3", "-c",
               "import nibrig, nibrig.measure\n"
               "print(nibrig.__file__)\n"
               "path = nibrig.measure.bundled_catalog()\n"
               "print(path)\n"
               "print('pairings', len(nibrig.measure.load_catalog(path).pairings))\n"},
              scratch);
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  EXPECT_NE(imported.output.find("/usr/lib/python3/dist-packages/nibrig/__init__.py\n"),
            std::string::npos)
      << imported.output;
  EXPECT_NE(imported.output.find("/usr/share/nibrig/assets/default_catalog.json\n"),
            std::string::npos)
      << imported.output;
  const auto bundled = read_json_file(nibrig::test::assets_dir() / "default_catalog.json");
  EXPECT_NE(imported.output.find("pairings " + std::to_string(bundled["pairings"].size()) + "\n"),
            std::string::npos)
      << imported.output;

  // The panel's libraries all resolve in the root (it needs a display to run).
  const auto linked = in_root(root, {"ldd", "/usr/bin/nibrig-panel"}, scratch);
  ASSERT_EQ(linked.exit_code, 0) << linked.output;
  EXPECT_EQ(linked.output.find("not found"), std::string::npos) << linked.output;

  outside();  // and nothing run inside created them
  EXPECT_TRUE(mounts_under(root).empty());
}

}  // namespace
}  // namespace nibrig::package
