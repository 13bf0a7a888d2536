#include "ui/cli/output.hpp"

#include <iostream>
#include <utility>
#include <vector>
#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"

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
  write_text_file(path, model::io::json_text(json, path));
}

CLI::Option* add_json_option(CLI::App* command, std::filesystem::path& file,
                             const std::string& holds) {
  return command
      ->add_option("--json", file, "Also write " + holds + " as JSON to this file, for a script")
      ->check(file_to_write());
}

void write_json_numbers(const std::filesystem::path& file, const nlohmann::json& numbers) {
  if (file.empty()) return;
  std::fflush(stdout);
  write_json_file(file, numbers);
  say_wrote(file);
}

void say_wrote(const std::filesystem::path& path) {
  // Written into a stream (-o /dev/stdout): the confirmation stays out of what was written.
  bool stream = false;
  try {
    stream = model::io::output_target(path).stream;
  } catch (const std::exception&) {
  }
  (stream ? std::cerr : std::cout) << "wrote " << path.string() << "\n";
}

namespace {
constexpr const char* kFileToWrite = "file to write";
}

CLI::Validator file_to_write() {
  CLI::Validator validator(
      [](std::string& text) -> std::string {
        try {
          model::io::output_target(text);  // a folder, a block device or a socket: refused here
        } catch (const std::exception& e) {
          return e.what();
        }
        return {};
      },
      "FILE");
  validator.name(kFileToWrite);
  return validator;
}

void refuse_outputs_that_are_inputs(CLI::App& command) {
  std::vector<std::pair<const CLI::Option*, std::string>> outputs, inputs;
  for (CLI::Option* option : command.get_options()) {
    bool is_output = false;
    try {
      option->get_validator(kFileToWrite);
      is_output = true;
    } catch (const CLI::OptionNotFound&) {
    }
    for (const std::string& value : option->results())
      (is_output ? outputs : inputs).emplace_back(option, value);
  }
  // Two outputs on one file: the second would replace the first. A stream (-o /dev/stdout) takes
  // both in turn, so only a regular file or a name not yet made counts.
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (std::size_t j = i + 1; j < outputs.size(); ++j) {
      const auto& [first_option, first] = outputs[i];
      const auto& [second_option, second] = outputs[j];
      std::error_code status_error, first_error, second_error;
      const auto status = std::filesystem::status(first, status_error);
      if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) continue;
      const auto first_path = std::filesystem::weakly_canonical(first, first_error);
      const auto second_path = std::filesystem::weakly_canonical(second, second_error);
      if (!first_error && !second_error && first_path == second_path)
        throw CLI::ValidationError(second_option->get_name(),
                                   second + ": is also " + first_option->get_name() +
                                       " of this command; one would replace the other: choose "
                                       "another file");
    }
  }
  for (const auto& [output_option, output] : outputs) {
    for (const auto& [input_option, input] : inputs) {
      std::error_code error;
      if (!std::filesystem::is_regular_file(input, error)) continue;
      if (std::filesystem::equivalent(output, input, error)) {
        const std::string name = input_option->get_name().empty() ? "an input"
                                                                   : input_option->get_name();
        throw CLI::ValidationError(output_option->get_name(),
                                   output + ": is also " + name + " of this command (" + input +
                                       "); writing it would replace what is being read: choose "
                                       "another file");
      }
    }
  }
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
