// What `-o` names is written as what it is (model/io/atomic_file.hpp): a link is written through,
// a device or a pipe as a stream, and an output that is also the command's input is refused
// before anything runs: a device node must never become a regular file.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path recording() {
  return nibrig::test::shared_data() / "piovarci2018/friction/real_tools/p2h_office_2.2N_14_1.csv.gz";
}

TEST(OutputTargetCli, ALinkIsWrittenThroughAndStaysALink) {
  const auto out = nibrig::test::scratch_dir("cli_output_link");
  std::ofstream(out / "kept.json") << "{}";
  fs::create_symlink("kept.json", out / "link.json");
  fs::create_symlink("/dev/null", out / "mynull");
  ASSERT_EQ(run_cli({"measure", recording().string(), "--no-plots", "-o", (out / "link.json").string()}), 0);
  EXPECT_TRUE(fs::is_symlink(out / "link.json"));
  EXPECT_NEAR(test::read_json(out / "kept.json")["mu"].get<double>(), 0.2, 0.15);  // a μ, not "{}"
  ASSERT_EQ(run_cli({"measure", recording().string(), "--no-plots", "-o", (out / "mynull").string()}), 0);
  EXPECT_TRUE(fs::is_symlink(out / "mynull"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(OutputTargetCli, APipeReceivesTheFileAsAStream) {
  const auto out = nibrig::test::scratch_dir("cli_output_fifo");
  const fs::path pipe = out / "pipe";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = read_bytes(pipe); });
  const int code = run_cli({"measure", recording().string(), "--no-plots", "-o", pipe.string()});
  reader.join();
  ASSERT_EQ(code, 0);
  EXPECT_TRUE(fs::is_fifo(pipe));
  const auto j = nlohmann::json::parse(received);
  EXPECT_EQ(j["kind"], "friction");
}

TEST(OutputTargetCli, AnOutputThatIsAlsoTheInputIsRefusedAndTheInputKept) {
  const auto out = nibrig::test::scratch_dir("cli_output_is_input");
  const fs::path copy = out / "p2h_office_2.2N_14_1.csv.gz";
  fs::copy_file(recording(), copy);
  const std::string before = read_bytes(copy);
  fs::create_symlink(copy.filename(), out / "alias.csv.gz");
  for (const fs::path& output : {copy, out / "alias.csv.gz"}) {
    SCOPED_TRACE(output.string());
    ::testing::internal::CaptureStderr();
    const int code = run_cli({"measure", copy.string(), "--no-plots", "-o", output.string()});
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(code, 0);
    EXPECT_NE(err.find("-o"), std::string::npos) << err;  // names the option
    EXPECT_EQ(read_bytes(copy), before);
  }
}

TEST(OutputTargetCli, AFolderIsRefusedWhileTheCommandLineIsRead) {
  const auto out = nibrig::test::scratch_dir("cli_output_folder");
  ::testing::internal::CaptureStderr();
  const int code = run_cli({"measure", recording().string(), "--no-plots", "-o", out.string()});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, 2);  // a usage error (ui/cli/README.md's exit codes)
  EXPECT_NE(err.find("is a folder"), std::string::npos) << err;
}

}  // namespace
}  // namespace nibrig::ui::cli
