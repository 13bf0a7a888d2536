// Running the `nibrig` command in-process from tests, and reading what it wrote.
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ui/cli/app.hpp"

namespace nibrig::test {

inline int run_cli(std::vector<std::string> args) {
  args.insert(args.begin(), "nibrig");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return ui::cli::run(static_cast<int>(argv.size()), argv.data());
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

}  // namespace nibrig::test
