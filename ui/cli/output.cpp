#include "ui/cli/output.hpp"

#include <iostream>
#include <stdexcept>

#include "model/io/atomic_file.hpp"

namespace nibrig::ui::cli {

void ensure_folder(const std::filesystem::path& folder) {
  if (folder.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) {
    throw std::runtime_error(folder.string() + ": cannot create folder: " + error.message());
  }
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  ensure_folder(path.parent_path());
  model::io::write_file_atomically(path, text);
}

void write_json_file(const std::filesystem::path& path, const nlohmann::json& json) {
  write_text_file(path, json.dump(2) + "\n");
}

void say_wrote(const std::filesystem::path& path) {
  std::cout << "wrote " << path.string() << "\n";
}

CLI::Validator file_to_write() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::error_code error;
        if (std::filesystem::is_directory(text, error))
          return text + ": is a folder; expected a file to write";
        return {};
      },
      "FILE");
}

std::string recording_stem(const std::filesystem::path& recording) {
  std::string name = recording.filename().string();
  if (name.empty()) name = recording.parent_path().filename().string();
  for (const char* suffix : {".csv.gz", ".csv"}) {
    const std::string s = suffix;
    if (name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0) {
      return name.substr(0, name.size() - s.size());
    }
  }
  return name;
}

}  // namespace nibrig::ui::cli
