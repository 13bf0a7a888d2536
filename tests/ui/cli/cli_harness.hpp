// Running the `nibrig` executable from tests, as a user would, and reading what it wrote. The
// command runs in a child process that inherits the test's standard output and error, so gtest's
// CaptureStdout/CaptureStderr see what it printed; the tests link no CLI code (ARCHITECTURE.md:
// nothing links nibrig_cli but the executable).
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace nibrig::test {

// Starts `nibrig args...` without waiting: its process id, for a test that signals it, then
// wait_cli(pid). With `input`, its standard input is read from that file (a person's keys,
// scripted); otherwise it inherits the test's. With `output`, its standard output goes to that
// file (for a test that waits for a prompt); otherwise to the test's. `errors` does the same for
// its standard error (for a test that waits for a log line).
inline pid_t start_cli(std::vector<std::string> args, const std::filesystem::path& input = {},
                       const std::filesystem::path& output = {},
                       const std::filesystem::path& errors = {}) {
  args.insert(args.begin(), NIBRIG_CLI_BINARY);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // What this process printed so far goes first, in order with the child's output.
  std::fflush(stdout);
  std::fflush(stderr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!input.empty()) posix_spawn_file_actions_addopen(&actions, 0, input.c_str(), O_RDONLY, 0);
  if (!output.empty()) posix_spawn_file_actions_addopen(&actions, 1, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!errors.empty())
    posix_spawn_file_actions_addopen(&actions, 2, errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
  pid_t pid = 0;
  const int e = posix_spawn(&pid, NIBRIG_CLI_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (e != 0)
    throw std::runtime_error(std::string("cannot start ") + NIBRIG_CLI_BINARY + ": error " +
                             std::to_string(e));
  return pid;
}

// The exit code of a started `nibrig`; 128 + the signal when it was killed by one.
inline int wait_cli(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("waitpid failed for " + std::string(NIBRIG_CLI_BINARY));
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + WTERMSIG(status);
}

// The exit code of `nibrig args...`; 128 + the signal when it was killed by one.
inline int run_cli(std::vector<std::string> args) { return wait_cli(start_cli(std::move(args))); }

// A file's whole text; empty when it cannot be read (yet).
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

inline bool is_png(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  return in && std::string(magic + 1, 3) == "PNG";
}

// The arguments with a coarser mesh and fewer modes than the stylus template's (4 mm and 32
// instead of 3 mm and 64: ~1 % in |H|, ~4x faster), for tests about a command rather than the
// model's resolution (the model's real-data tests use the full one).
inline std::vector<std::string> with_coarse(std::vector<std::string> args) {
  for (const char* a : {"--modes", "32", "--mesh-size", "0.004"}) args.emplace_back(a);
  return args;
}

}  // namespace nibrig::test
